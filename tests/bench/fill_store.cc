// rlpos-bench-fill-store: a results database of a large campaign in seconds, for the campaign
// page's benchmark (scripts/bench_campaign_page.sh). Expands a campaign of fixed positioners
// (baseline, centroid, oracle; no training) into the store as the coordinator would, then records
// every job's success with made-up but plausible numbers, through the store's own ledger and
// recorder. The numbers are deterministic: the same campaign gives the same database rows.
//   rlpos-bench-fill-store CAMPAIGN.json DB [--leave N]   (--leave: the last N jobs stay queued)
#include <algorithm>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

#include "common/campaign/expansion.h"
#include "common/config/config_error.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/program_usage.h"

namespace rlpos {
namespace {

// A position inside the scenario's zone for each fixed positioner.
Vec3 PositionOf(const Scenario& s, const std::string& positioner) {
  const UavSpec& uav = s.uavs.front();
  Vec3 p = uav.initial;
  if (positioner == "centroid" && !s.ues.empty()) {
    p = {0, 0, uav.initial.z};
    for (const auto& ue : s.ues) {
      p.x += ue.position.x / s.ues.size();
      p.y += ue.position.y / s.ues.size();
    }
  } else if (positioner == "oracle") {
    p = {uav.initial.x - 12, uav.initial.y - 9, uav.initial.z + 6};
  }
  p.x = std::clamp(p.x, uav.zone.xmin, uav.zone.xmax);
  p.y = std::clamp(p.y, uav.zone.ymin, uav.zone.ymax);
  p.z = std::clamp(p.z, uav.zone.zmin, uav.zone.zmax);
  return p;
}

// An eval's metrics: a level per positioner, spread per run.
nlohmann::json EvalResultOf(const Job& job, const Placement& placement, int n_ues) {
  const double level = job.label == "oracle" ? 230 : job.label == "centroid" ? 200 : 160;
  std::mt19937_64 rng(std::hash<std::string>{}(job.key));
  std::normal_distribution<double> spread(1.0, 0.06);
  const double mbps = level * std::max(0.5, spread(rng));
  const Vec3& p = placement.front();
  return {{"position", {p.x, p.y, p.z}},
          {"window_s", {0.5, 2.0}},
          {"run", *job.params.rng_run},
          {"aggregate_throughput_mbps", mbps},
          {"mean_delay_ms", 5 + 3000 / mbps * spread(rng)},
          {"loss_ratio", 0.01},
          {"n_los", job.label == "baseline" ? 1 : n_ues},
          {"n_ues", n_ues},
          {"demands_met", job.label == "baseline" ? 1 : n_ues},
          {"min_snr_db", 12.5 * spread(rng)},
          {"worst_ue_throughput_mbps", mbps / n_ues * 0.8},
          {"jain_fairness", std::min(1.0, 0.9 * spread(rng))},
          {"ues", nlohmann::json::array()},
          {"scenario", job.params.scenario}};
}

const Scenario& ScenarioNamed(const CampaignSpec& spec, const std::string& name) {
  for (const auto& s : spec.scenarios) {
    if (s.scenario.name == name)
      return s.scenario;
  }
  throw std::invalid_argument("no scenario " + name);
}

void Record(CoordinatorStore& store, const CampaignSpec& spec, const Job& job) {
  if (!store.ledger.MarkRunning(job.id, "bench-worker", 0, 1))
    throw std::runtime_error(job.id + ": not ready");
  const Scenario& scenario = ScenarioNamed(spec, job.params.scenario);
  nlohmann::json result;
  if (job.params.kind == JobKind::kEval) {
    const auto bound = store.reader.GetJob(job.id);
    result = EvalResultOf(job, *bound->placement, static_cast<int>(scenario.ues.size()));
  } else {
    const Vec3 p = PositionOf(scenario, job.label);
    result = {{"position", {p.x, p.y, p.z}}, {"n_los", 4}, {"reward", 0.9}};
  }
  if (store.recorder.RecordSuccess(job.id, 1, result) != JobUpdate::kSucceeded)
    throw std::runtime_error(job.id + ": result refused");
}

int Fill(const std::string& campaign_file, const std::string& db, std::size_t leave) {
  const CampaignSpec spec = ReadCampaignFile(campaign_file);
  if (spec.NeedsTraining())
    throw std::invalid_argument(campaign_file + ": fixed positioners only (no rl, no offsets)");
  ExpandedCampaign campaign = ExpandCampaign(spec);
  CoordinatorStore store(db);
  store.ledger.Submit(campaign);
  const std::size_t to_record = campaign.jobs.size() - std::min(leave, campaign.jobs.size());
  for (std::size_t begin = 0; begin < to_record; begin += 500) {
    StoreBatch batch = store.db.Batch();
    for (std::size_t i = begin; i < std::min(to_record, begin + 500); ++i)
      Record(store, spec, campaign.jobs[i]);
    batch.Commit();
  }
  std::printf("campaign %s: %zu jobs, %zu recorded\n", campaign.id.c_str(), campaign.jobs.size(),
              to_record);
  return 0;
}

}  // namespace
}  // namespace rlpos

int main(int argc, char** argv) {
  constexpr char kUsage[] = "usage: rlpos-bench-fill-store CAMPAIGN.json DB [--leave N]\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--leave"))
    return rlpos::testing::UsageError(kUsage);
  try {
    return rlpos::Fill(argv[1], argv[2], argc == 5 ? std::stoul(argv[4]) : 0);
  } catch (const rlpos::ConfigError& e) {
    std::fprintf(stderr, "rlpos-bench-fill-store: %s: %s\n", argv[1], e.describe().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rlpos-bench-fill-store: %s\n", e.what());
  }
  return 2;
}
