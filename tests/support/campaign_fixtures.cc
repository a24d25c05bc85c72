#include "tests/support/campaign_fixtures.h"

#include <sqlite3.h>

#include <sstream>

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

namespace {

template <typename T>
std::string Text(const std::optional<T>& v) {
  if (!v)
    return "unset";
  std::ostringstream out;
  out << *v;
  return out.str();
}

// Doubles as text that reads back exactly: equal text, equal number.
std::string Text(const std::optional<double>& v) {
  return v ? FormatNumber(*v) : "unset";
}

std::string Text(const std::vector<ScenarioOverride>& overrides) {
  std::string out = "[";
  for (const auto& o : overrides)
    out += (out.size() > 1 ? ", " : "") + ToString(o);
  return out + "]";
}

}  // namespace

::testing::AssertionResult SameParams(const JobParams& a, const JobParams& b) {
  std::string diff;
  const auto field = [&diff](const char* name, const std::string& x, const std::string& y) {
    if (x != y)
      diff += std::string(" ") + name + ": " + x + " vs " + y + ";";
  };
  field("kind", ToString(a.kind), ToString(b.kind));
  field("scenario", a.scenario, b.scenario);
  field("train_seed", Text(a.train_seed), Text(b.train_seed));
  field("fidelity", a.fidelity, b.fidelity);
  field("train_episodes", Text(a.train_episodes), Text(b.train_episodes));
  field("positioner", a.positioner, b.positioner);
  field("rng_run", Text(a.rng_run), Text(b.rng_run));
  field("duration_s", Text(a.duration_s), Text(b.duration_s));
  field("warmup_s", Text(a.warmup_s), Text(b.warmup_s));
  field("overrides", Text(a.overrides), Text(b.overrides));
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
