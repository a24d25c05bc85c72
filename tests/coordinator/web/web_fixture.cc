#include "tests/coordinator/web/web_fixture.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/hash/sha256.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos::web::testing {
namespace {

std::string ReadBytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

class Recorder {
 public:
  Recorder(CoordinatorStore& store, const std::string& campaign_id)
      : store_(store), campaign_id_(campaign_id) {}

  void Produce(const std::string& key, std::vector<ArtifactFile> artifacts = {}) {
    const std::string id = campaign_id_ + "/" + key;
    ASSERT_TRUE(store_.ledger.MarkRunning(id, "w1", 0, 1)) << key;
    ASSERT_EQ(store_.recorder.RecordSuccess(id, 1, rlpos::testing::PositionResult(50, 35, 10), "",
                                            nullptr, artifacts),
              JobUpdate::kSucceeded)
        << key;
  }

  // `reward`: the placement's analytic reward, which the optimality table compares.
  void Eval(const std::string& scenario, const std::string& label, int run, double mbps,
            std::optional<double> reward = std::nullopt) {
    const std::string id =
        campaign_id_ + "/eval/" + scenario + "/" + label + "/run" + std::to_string(run);
    nlohmann::json eval = rlpos::testing::EvalResult(run, mbps, 2.0 + run);
    if (reward)
      eval["reward"] = *reward;
    const auto result = rlpos::testing::AtJobPosition(store_.reader, id, eval);
    ASSERT_TRUE(store_.ledger.MarkRunning(id, "w1", 0, 1)) << id;
    ASSERT_EQ(store_.recorder.RecordSuccess(id, 1, result), JobUpdate::kSucceeded) << id;
  }

  void Fail(const std::string& key, const std::string& error) {
    const std::string id = campaign_id_ + "/" + key;
    for (int attempt = 1;; ++attempt) {
      ASSERT_TRUE(store_.ledger.MarkRunning(id, "w1", 0, attempt));
      if (store_.ledger.RecordFailure(id, attempt, error) == JobUpdate::kFailed)
        return;
    }
  }

 private:
  CoordinatorStore& store_;
  std::string campaign_id_;
};

ArtifactFile Artifact(const std::string& name, const std::string& data) {
  return {name, Sha256Hex(data), data};
}

}  // namespace

CampaignDb::CampaignDb() : file_(dir_.File("rlpos.db")), campaign_(rlpos::testing::MiniCampaign()) {
  CoordinatorStore store(file_);
  store.ledger.Submit(campaign_);
  Recorder r(store, campaign_.id);
  r.Produce("position/B/baseline");
  r.Produce("position/B/centroid");
  r.Produce("position/B/oracle");
  r.Produce("train/B/seed1",
            {Artifact("learning_curve.csv",
                      "episode,phase,total_reward,mean_loss,epsilon\n1,train,1.5,0.5,1\n"
                      "2,train,2.5,0.25,0.5\n3,train,3.5,0.125,0.25\n1,eval,3,0,0\n")});
  r.Produce("position/C/oracle");
  r.Eval("B", "baseline", 1, 100);
  r.Eval("B", "baseline", 2, 120);
  r.Eval("B", "centroid", 1, 110);
  r.Eval("B", "oracle", 1, 200, 0.9);
  r.Eval("B", "oracle", 2, 200, 0.9);
  r.Eval("B", "rl", 1, 150, 0.72);
  r.Eval("B", "rl", 2, 170, 0.72);
  r.Eval("C", "oracle", 1, 80);
  r.Fail("eval/B/centroid/run2", "exit code 1: \"boom\"\nsecond line");
}

std::string CampaignDb::Hash() const {
  std::string bytes = ReadBytes(file_);
  if (std::filesystem::exists(file_ + "-wal"))
    bytes += ReadBytes(file_ + "-wal");
  return Sha256Hex(bytes);
}

void CampaignDb::Exec(const std::string& sql) const {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file_.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
  const std::string message = error ? error : "";
  sqlite3_free(error);
  sqlite3_close(db);
  ASSERT_EQ(rc, SQLITE_OK) << message;
}

}  // namespace rlpos::web::testing
