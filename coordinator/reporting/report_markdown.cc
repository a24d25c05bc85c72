#include "reporting/report_markdown.h"

#include "reporting/results_format.h"

namespace rlpos {
namespace {

std::string Jobs(int n) {
  return std::to_string(n) + (n == 1 ? " job" : " jobs");
}

}  // namespace

std::string FormatReportMarkdown(const CampaignProgress& progress,
                                 const std::vector<PositionerSummary>& summary) {
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
  return out;
}

}  // namespace rlpos
