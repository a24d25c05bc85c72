// The report's figures of track runs: the distributions over the RngRuns of each run's time
// means (CCDF for throughput, CDF for the rest, runs without a value left out), the time series
// in the summary's order, and the PNGs plot_campaign.py draws from their CSVs.
#include "coordinator/reporting/track_curves.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>

#include "common/files/atomic_file.h"
#include "coordinator/reporting/plot_script.h"
#include "tests/support/campaign_fixtures.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;

TrackRunRow RunOf(const std::string& scenario, const std::string& label, double reward, double mbps,
                  double delay) {
  TrackRunRow r;
  r.scenario = scenario;
  r.label = label;
  r.metrics.mean_reward = reward;
  r.metrics.mean_throughput_mbps = mbps;
  r.metrics.mean_delay_ms = delay;
  r.metrics.outage_share = 0.25;
  return r;
}

std::vector<TrackRunRow> Runs() {
  const double none = std::numeric_limits<double>::quiet_NaN();
  return {RunOf("street", "oracle-track", 0.8, 30, none), RunOf("street", "oracle", 0.5, 10, 4),
          RunOf("street", "oracle-track", 0.6, 20, none), RunOf("festival", "centroid", 0.4, 5, 2)};
}

std::vector<std::string> Curve(const std::vector<TrackCurvePoint>& points,
                               const std::string& scenario, const std::string& positioner,
                               const std::string& metric) {
  std::vector<std::string> out;
  for (const TrackCurvePoint& p : points) {
    if (p.scenario == scenario && p.positioner == positioner && p.metric == metric)
      out.push_back(std::to_string(static_cast<int>(p.x * 10)) + (p.above ? ">" : "<=") +
                    std::to_string(p.p).substr(0, 4));
  }
  return out;
}

TEST(TrackCurves, EachRunsTimeMeansOverTheRunsCcdfForThroughput) {
  const auto points = TrackDistributions(Runs());
  EXPECT_EQ(Curve(points, "street", "oracle-track", "mean_throughput_mbps"),
            (std::vector<std::string>{"200>0.50", "300>0.00"}));
  EXPECT_EQ(Curve(points, "street", "oracle-track", "mean_reward"),
            (std::vector<std::string>{"6<=0.50", "8<=1.00"}));
  EXPECT_TRUE(Curve(points, "street", "oracle-track", "mean_delay_ms").empty())
      << "no run of oracle-track has a delay";
  EXPECT_EQ(Curve(points, "street", "oracle", "mean_delay_ms"),
            (std::vector<std::string>{"40<=1.00"}));
  EXPECT_EQ(Curve(points, "festival", "centroid", "outage_share"),
            (std::vector<std::string>{"2<=1.00"}));
  // The summary's order: street before festival (as they came), held oracle before tracking.
  std::vector<std::string> order;
  for (const TrackCurvePoint& p : points) {
    const std::string group = p.scenario + "/" + p.positioner;
    if (order.empty() || order.back() != group)
      order.push_back(group);
  }
  EXPECT_EQ(order, (std::vector<std::string>{"street/oracle", "street/oracle-track",
                                             "festival/centroid"}));
  const std::string csv = FormatTrackDistributionsCsv(points);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "scenario,positioner,metric,p_is,x,p");
  EXPECT_NE(csv.find("\nstreet,oracle-track,mean_throughput_mbps,above,20,0.5\n"),
            std::string::npos)
      << csv;
}

TrackSeriesRow Interval(const std::string& scenario, const std::string& label, int interval) {
  TrackSeriesRow r;
  r.scenario = scenario;
  r.label = label;
  r.interval = interval;
  r.time_s = interval + 1.0;
  r.runs = 2;
  r.scored = interval > 0;
  return r;
}

TEST(TrackCurves, SeriesInTheSummarysOrderEachPositionersIntervalsInTurn) {
  // As SQLite returns them: scenarios in campaign order, positioners by name.
  const auto rows = OrderTrackSeries(
      {Interval("street", "oracle-track", 0), Interval("street", "oracle-track", 1),
       Interval("street", "rl+generalist", 0), Interval("street", "zeta", 0),
       Interval("street", "oracle", 0), Interval("street", "oracle", 1),
       Interval("festival", "centroid", 0)});
  std::vector<std::string> order;
  for (const TrackSeriesRow& r : rows)
    order.push_back(r.scenario + "/" + r.label + "/" + std::to_string(r.interval));
  EXPECT_EQ(order,
            (std::vector<std::string>{"street/oracle/0", "street/oracle/1", "street/oracle-track/0",
                                      "street/oracle-track/1", "street/rl+generalist/0",
                                      "street/zeta/0", "festival/centroid/0"}));
  const std::string csv = FormatTrackSeriesCsv(rows);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scenario,positioner,interval,time_s,runs,scored,reward,throughput_mbps,delay_ms,"
            "los_share,demands_met_share");
  EXPECT_NE(csv.find("\nstreet,oracle,0,1,2,0,0,0,,0,0\n"), std::string::npos) << csv;
}

bool PythonCanPlot() {
  return std::system("python3 -c 'import matplotlib' >/dev/null 2>&1") == 0 ||
         std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

TEST(TrackCurves, PlottedPerScenarioAsPngs) {
  if (!PythonCanPlot())
    GTEST_SKIP() << "python3 with matplotlib not found";
  testing::TempDir dir;
  const auto write = [&](const std::string& name, const std::string& content) {
    WriteFileAtomically(dir.File(name), content);
    return dir.File(name);
  };
  std::vector<TrackSeriesRow> series;
  for (const char* label : {"oracle", "oracle-track"}) {
    for (int i = 0; i < 5; ++i) {
      TrackSeriesRow r = Interval("street", label, i);
      r.reward = 0.5 + 0.05 * i;
      series.push_back(r);
    }
  }
  PlotRequest request;
  request.script = testing::SourcePath("scripts/plot_campaign.py");
  request.throughput_csv = write("throughput_ccdf.csv", "scenario,positioner,x,p\n");
  request.delay_csv = write("delay_cdf.csv", "scenario,positioner,x,p\n");
  request.track_distributions_csv =
      write("track_distributions.csv", FormatTrackDistributionsCsv(TrackDistributions(Runs())));
  request.track_series_csv = write("track_series.csv", FormatTrackSeriesCsv(series));
  request.out_dir = dir.File("");
  const PlotOutcome outcome = RenderPlots(request);
  ASSERT_TRUE(outcome.warnings.empty()) << outcome.warnings[0];
  std::vector<std::string> names;
  for (const std::string& file : outcome.files) {
    names.push_back(fs::path(file).filename().string());
    EXPECT_EQ(testing::ReadFile(file).substr(1, 3), "PNG") << file;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"track_distributions_street.png",
                                             "track_distributions_festival.png",
                                             "track_series_street.png"}));
}

}  // namespace
}  // namespace rlpos
