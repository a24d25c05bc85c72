#include "test_support.h"

namespace rlpos::testing {

std::string SourcePath(const std::string& relative) {
  return std::string(RLPOS_SOURCE_DIR) + "/" + relative;
}

CampaignSpec MiniSpec() {
  return ReadCampaignFile(SourcePath("campaigns/mini.json"));
}

ExpandedCampaign MiniCampaign() {
  return ExpandCampaign(MiniSpec());
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

nlohmann::json AtJobPosition(ResultsStore& store, const std::string& job_id,
                             nlohmann::json result) {
  const auto job = store.GetJob(job_id);
  if (job && job->position) {
    result["position"] = {job->position->x, job->position->y, job->position->z};
  }
  return result;
}

}  // namespace rlpos::testing
