#include "coordinator/reporting/report_markdown.h"

#include "coordinator/reporting/optimality.h"
#include "coordinator/reporting/results_format.h"

namespace rlpos {
namespace {

std::string Jobs(int n) {
  return std::to_string(n) + (n == 1 ? " job" : " jobs");
}

}  // namespace

std::string FormatReportMarkdown(const CampaignProgress& progress,
                                 const std::vector<PositionerSummary>& summary,
                                 const std::vector<UavSummary>& uavs) {
  const CampaignProgress& p = progress;
  std::string out = "# Campaign report: " + p.name + "\n\n";
  out += "- Campaign id: `" + p.campaign_id + "`\n";
  out += "- State: " + p.state + "\n";
  out += "- Jobs: " + std::to_string(p.total) + " in all: " + std::to_string(p.succeeded) +
         " succeeded, " + std::to_string(p.failed) + " failed, " + std::to_string(p.cancelled) +
         " cancelled, " + std::to_string(p.running) + " running, " + std::to_string(p.ready) +
         " ready, " + std::to_string(p.pending) + " pending\n\n";
  if (p.failed > 0) {
    out += "> **Note:** " + Jobs(p.failed) +
           " failed (see the `error` column of the `jobs` table). Their eval runs, and those of "
           "evals that depended on a failed train or position job, are missing from the "
           "numbers below; `retry` brings failed jobs back.\n\n";
  }
  out += "## Summary per scenario and positioner\n\n";
  if (summary.empty()) {
    out += "No eval run has succeeded yet.\n\n";
  }
  out += FormatSummaryMarkdown(summary);
  out +=
      "\nOver the succeeded eval runs of each scenario and positioner: aggregate throughput "
      "(median, mean and the half width of its 95 % confidence interval, Student t; \"-\" for "
      "one run), mean delay over the runs that received packets (\"no delay\": runs that "
      "received nothing, left out), mean share of UEs in line of sight (nLoS/N), mean number "
      "of UEs whose demand is met, and the change of the mean throughput and mean delay "
      "against the scenario's baseline in % (\"-\" without a baseline).\n\n"
      "Files: `summary.csv` (these numbers unrounded), `throughput_ccdf.csv` and `delay_cdf.csv` "
      "(the curves), `throughput_ccdf_<scenario>.png` and `delay_cdf_<scenario>.png` (plots).\n";
  if (uavs.empty())
    return out;
  out += "\n## Per UAV, in the scenarios with several\n\n";
  out += FormatUavSummaryMarkdown(uavs);
  out +=
      "\nEach UAV's share of the same runs: the UEs associated with it (best SNR, or the "
      "scenario's fixed assignment), their aggregate throughput (mean, 95 % CI), mean delay over "
      "the runs in which they received packets, how many of them see it in line of sight, its "
      "worst UE's throughput and Jain's fairness index over its UEs (over the runs in which it "
      "served any). In the table above, throughput, nLoS, worst UE and Jain are over all UEs "
      "whichever UAV serves them. File: `uav_summary.csv`; per run: the view `v_eval_uavs`.\n";
  return out;
}

std::string FormatOptimalitySection(const std::vector<OptimalityRow>& rows) {
  const std::vector<OptimalitySummary> summary = SummarizeOptimality(rows);
  if (summary.empty())
    return "";
  std::string out = "\n## Optimality: each placement against the oracle\n\n";
  out += FormatOptimalityMarkdown(summary);
  out +=
      "\nA run is one placement: rl's (one scenario, algorithm and train seed), a named policy's "
      "(`rl+<name>`: a policy trained elsewhere, for any scenario or for this one, placing with no "
      "training here), or another positioner's, per scenario; its ratio is its reward over the "
      "oracle's at the same scenario, both the env's reward (`env.reward`) of the placement by "
      "the analytic model, the `reward` of their evals. With several UAVs the oracle is a "
      "coordinate descent, which rl may beat (a ratio above 1). Per algorithm (named policy, "
      "positioner) and number of UAVs: the median ratio, its 10th percentile (P10), the worst "
      "run, the runs at or above 0.95, and the median wall seconds of the job that found a "
      "placement (a training, or a position job with its process start). Files: "
      "`optimality.csv` (every run), `optimality_summary.csv`, `optimality_cdf.csv` and "
      "`optimality_cdf.png` (the ratio's CDF).\n";
  const std::vector<OptimalityRow> below = RunsBelowNearOptimal(rows);
  if (!below.empty()) {
    out += "\n### rl runs under 95 % of the oracle, worst first\n\n";
    out += FormatOptimalityRowsMarkdown(below);
  }
  return out;
}

}  // namespace rlpos
