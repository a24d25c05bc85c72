// The track runs' summary: one row per scenario and positioner (each named policy its own), in
// campaign order, held positioners before tracking ones, each metric averaged over the runs that
// have it.
#include "coordinator/reporting/track_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace rlpos {
namespace {

TrackRunRow TrackRun(const std::string& scenario, const std::string& label, std::int64_t run,
                     double reward, double delay) {
  TrackRunRow r;
  r.scenario = scenario;
  r.label = label;
  r.rng_run = run;
  r.fidelity = "packet";
  r.metrics.mean_reward = reward;
  r.metrics.mean_delay_ms = delay;
  return r;
}

TEST(TrackSummary, OneRowPerScenarioAndPositionerInReportOrder) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  const std::vector<TrackRunRow> rows{TrackRun("street", "rl+b", 1, 0.9, 2),
                                      TrackRun("street", "oracle-track", 1, 0.8, 4),
                                      TrackRun("street", "rl+a", 1, 0.7, none),
                                      TrackRun("street", "oracle", 1, 0.5, 6),
                                      TrackRun("street", "oracle-track", 2, 0.6, none),
                                      TrackRun("festival", "centroid", 1, 0.4, 1)};
  const std::vector<TrackSummary> summary = SummarizeTracks(rows);
  std::vector<std::string> order;
  for (const TrackSummary& s : summary)
    order.push_back(s.scenario + "/" + s.positioner + "/" + std::to_string(s.runs));
  EXPECT_EQ(order,
            (std::vector<std::string>{"street/oracle/1", "street/oracle-track/2", "street/rl+a/1",
                                      "street/rl+b/1", "festival/centroid/1"}));
  const TrackSummary& tracking = summary[1];
  EXPECT_DOUBLE_EQ(*tracking.means[0], 0.7);  // mean_reward: (0.8 + 0.6) / 2
  EXPECT_DOUBLE_EQ(*tracking.means[4], 4.0);  // mean_delay_ms: the run that has one
  EXPECT_FALSE(summary[2].means[4].has_value()) << "no run of rl+a has a delay";
  const std::string csv = FormatTrackSummaryCsv(summary);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scenario,positioner,fidelity,runs,mean_reward,reward_p5,mean_throughput_mbps,"
            "throughput_p5_mbps,mean_delay_ms,los_share,los_share_p5,outage_share,"
            "demands_met_share_p5,distance_flown_m,handovers");
  EXPECT_EQ(FormatTrackSummaryMarkdown({}), "");
}

}  // namespace
}  // namespace rlpos
