#include "coordinator/reporting/campaign_summary.h"

#include <map>

#include "common/stats/descriptive.h"
#include "coordinator/reporting/run_groups.h"

namespace rlpos {
namespace {

PositionerSummary Summarize(const RunGroup& group) {
  PositionerSummary s;
  s.scenario = group.scenario;
  s.positioner = group.label;
  s.runs = static_cast<int>(group.runs.size());
  std::vector<double> throughput, delay, nlos_ratio, demands_met, ues, worst_ue, jain;
  for (const MetricRow* run : group.runs) {
    throughput.push_back(run->aggregate_throughput_mbps.value_or(0));
    if (run->mean_delay_ms) {
      delay.push_back(*run->mean_delay_ms);
    } else {
      ++s.delay_null_runs;
    }
    if (run->n_ues > 0)
      nlos_ratio.push_back(static_cast<double>(run->n_los) / run->n_ues);
    demands_met.push_back(run->demands_met);
    ues.push_back(run->n_ues);
    if (run->worst_ue_throughput_mbps)
      worst_ue.push_back(*run->worst_ue_throughput_mbps);
    if (run->jain_fairness)
      jain.push_back(*run->jain_fairness);
  }
  const ConfidenceInterval throughput_ci = MeanConfidenceInterval(throughput);
  s.throughput_mean_mbps = throughput_ci.mean;
  s.throughput_ci95_mbps = throughput_ci.half_width;
  s.throughput_median_mbps = Median(throughput);
  s.delay_runs = static_cast<int>(delay.size());
  if (!delay.empty()) {
    const ConfidenceInterval delay_ci = MeanConfidenceInterval(delay);
    s.delay_mean_ms = delay_ci.mean;
    s.delay_ci95_ms = delay_ci.half_width;
  }
  if (!nlos_ratio.empty())
    s.nlos_ratio_mean = Mean(nlos_ratio);
  s.demands_met_mean = Mean(demands_met);
  s.ues_mean = Mean(ues);
  if (!worst_ue.empty())
    s.worst_ue_mean_mbps = Mean(worst_ue);
  if (!jain.empty())
    s.jain_mean = Mean(jain);
  return s;
}

}  // namespace

std::vector<PositionerSummary> SummarizeRuns(const std::vector<MetricRow>& rows) {
  std::vector<PositionerSummary> out;
  for (const RunGroup& group : GroupRuns(rows))
    out.push_back(Summarize(group));
  std::map<std::string, const PositionerSummary*> baselines;
  for (const auto& s : out) {
    if (s.positioner == "baseline")
      baselines[s.scenario] = &s;
  }
  for (auto& s : out) {
    const auto found = baselines.find(s.scenario);
    if (found == baselines.end())
      continue;
    const PositionerSummary& base = *found->second;
    s.throughput_change_pct = ChangePercent(s.throughput_mean_mbps, base.throughput_mean_mbps);
    if (s.delay_mean_ms && base.delay_mean_ms) {
      s.delay_change_pct = ChangePercent(*s.delay_mean_ms, *base.delay_mean_ms);
    }
  }
  return out;
}

std::vector<PositionerSummary> SummarizeCampaign(ResultsReader& store,
                                                 const std::string& campaign_id) {
  store.Progress(campaign_id);  // throws StoreError for an unknown campaign
  return SummarizeRuns(store.Metrics(campaign_id));
}

}  // namespace rlpos
