#include "tests/support/campaign_fixtures.h"

#include "common/job/job_fields.h"
#include "common/scenario/number_text.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"

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
  try {
    Database db(db_file, /*read_only=*/true, /*busy_timeout_ms=*/0);
    // A common table expression names the query's one value, whatever its expression, so that
    // it is read by name.
    Statement one = db.Prepare("WITH one(value) AS (" + sql + ") SELECT value FROM one");
    const ResultColumn value = one.Column("value");
    return one.Step() ? one.OptionalText(value).value_or("<null>") : "<no row>";
  } catch (const StoreError& e) {
    return e.what();
  }
}

}  // namespace rlpos::testing
