#include "tests/support/campaign_fixtures.h"

#include <sqlite3.h>

#include "common/job/job_fields.h"
#include "common/scenario/number_text.h"

namespace rlpos::testing {

std::string SourcePath(const std::string& relative) {
  return std::string(RLPOS_SOURCE_DIR) + "/" + relative;
}

CampaignSpec MiniSpec() {
  return ReadCampaignFile(SourcePath("campaigns/mini.json"));
}

ExpandedCampaign MiniCampaign() {
  ExpandedCampaign campaign = ExpandCampaign(MiniSpec());
  // The tests' stand-in results put many positions at one place, which the result cache would
  // rightly run once; the cache has its own tests (result_cache_test.cc).
  campaign.use_cache = false;
  return campaign;
}

const Job& FindJob(const ExpandedCampaign& campaign, const std::string& key) {
  for (const auto& job : campaign.jobs) {
    if (job.key == key)
      return job;
  }
  throw std::out_of_range("no job " + key);
}

nlohmann::json PositionResult(double x, double y, double z) {
  return {{"position", {x, y, z}}, {"n_los", 4}, {"reward", 0.9}};
}

nlohmann::json EvalResult(std::uint64_t run, double throughput_mbps, double delay_ms) {
  return {{"position", {50.0, 35.0, 10.0}},
          {"window_s", {0.5, 2.0}},
          {"run", run},
          {"aggregate_throughput_mbps", throughput_mbps},
          {"mean_delay_ms", delay_ms},
          {"loss_ratio", 0.01},
          {"n_los", 4},
          {"n_ues", 4},
          {"demands_met", 3},
          {"min_snr_db", 12.5},
          {"ues", nlohmann::json::array()},
          {"scenario", "B"}};
}

::testing::AssertionResult SameParams(const JobParams& a, const JobParams& b) {
  std::vector<std::string> texts;  // a's fields, in declaration order
  ForEachField(a,
               [&](const auto&, const auto& value) { texts.push_back(FieldJson(value).dump()); });
  std::string diff;
  std::size_t i = 0;
  ForEachField(b, [&](const auto& field, const auto& value) {
    const std::string text = FieldJson(value).dump();
    if (texts[i] != text)
      diff += std::string(" ") + field.name + ": " + texts[i] + " vs " + text + ";";
    ++i;
  });
  if (diff.empty())
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "params differ:" << diff;
}

nlohmann::json AtJobPosition(ResultsReader& store, const std::string& job_id,
                             nlohmann::json result) {
  const auto job = store.GetJob(job_id);
  if (job && job->placement) {
    const Placement& placement = *job->placement;
    result["position"] = {placement[0].x, placement[0].y, placement[0].z};
    for (std::size_t i = 0; result.contains("uavs") && i < result["uavs"].size(); ++i) {
      const Vec3& p = placement.at(i);
      result["uavs"][i]["position"] = {p.x, p.y, p.z};
    }
  }
  return result;
}

std::string FormatPlacement(const std::optional<Placement>& placement) {
  if (!placement)
    return "unbound";
  std::string text;
  for (const Vec3& p : *placement)
    text += (text.empty() ? "" : " ") + FormatPosition(p);
  return text;
}

std::string QueryOne(const std::string& db_file, const std::string& sql) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(db_file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* stmt = nullptr;
  std::string out = "<no row>";
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr) != SQLITE_OK) {
    out = sqlite3_errmsg(db);
  } else if (sqlite3_step(stmt) == SQLITE_ROW) {
    const auto* text = sqlite3_column_text(stmt, 0);
    out = text ? reinterpret_cast<const char*>(text) : "<null>";
  }
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  return out;
}

}  // namespace rlpos::testing
