// The per-UAV summary of `rlpos-campaign results --per-uav` and the report: numbers against
// values computed by hand, which scenarios and in what order, and the renderings.
#include "coordinator/reporting/uav_summary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rlpos {
namespace {

UavMetricRow Row(const std::string& scenario, const std::string& label, std::int64_t run, int uav,
                 int served, double throughput, std::optional<double> delay,
                 std::optional<double> worst, std::optional<double> jain) {
  UavMetricRow r;
  r.scenario = scenario;
  r.label = label;
  r.rng_run = run;
  r.uav = uav;
  r.name = uav == 0 ? "north" : "south";
  r.ues_served = served;
  r.throughput_mbps = throughput;
  r.mean_delay_ms = delay;
  r.n_los = served / 2;
  r.worst_ue_throughput_mbps = worst;
  r.jain_fairness = jain;
  return r;
}

std::vector<UavMetricRow> UavRows() {
  return {
      Row("one", "baseline", 1, 0, 4, 100, 5, 10, 0.9),  // a single-UAV scenario: left out
      Row("two", "rl", 1, 0, 6, 300, 10, 40, 0.8),
      Row("two", "rl", 1, 1, 2, 50, std::nullopt, 0, 0.5),
      Row("two", "rl", 2, 0, 4, 200, 20, 30, 0.6),
      Row("two", "rl", 2, 1, 0, 0, std::nullopt, std::nullopt, std::nullopt),
      Row("two", "baseline", 1, 0, 8, 100, 1, 5, 1.0),
      Row("two", "baseline", 1, 1, 0, 0, std::nullopt, std::nullopt, std::nullopt),
  };
}

TEST(UavSummary, MeansPerUavOverItsRuns) {
  const std::vector<UavSummary> s = SummarizeUavs(UavRows());
  ASSERT_EQ(s.size(), 4u);
  // Report order: baseline before rl, UAVs in scenario order.
  EXPECT_EQ(s[0].positioner, "baseline");
  EXPECT_EQ(s[0].name, "north");
  EXPECT_EQ(s[1].name, "south");
  EXPECT_EQ(s[2].positioner, "rl");
  const UavSummary& north = s[2];
  EXPECT_EQ(north.runs, 2);
  EXPECT_DOUBLE_EQ(north.ues_served_mean, 5);
  EXPECT_DOUBLE_EQ(north.throughput_mean_mbps, 250);
  // Two runs 300 and 200: s = 70.71, t(0.975, 1) = 12.706 -> 12.706 * 70.71 / sqrt(2) = 635.3.
  EXPECT_NEAR(north.throughput_ci95_mbps, 12.7062 * 50, 0.01);
  EXPECT_DOUBLE_EQ(north.delay_mean_ms.value(), 15);
  EXPECT_DOUBLE_EQ(north.nlos_mean, 2.5);
  EXPECT_DOUBLE_EQ(north.worst_ue_mean_mbps.value(), 35);
  EXPECT_DOUBLE_EQ(north.jain_mean.value(), 0.7);
  // The south UAV served nobody in run 2: its worst UE and Jain are over run 1 only, its delay
  // over none.
  const UavSummary& south = s[3];
  EXPECT_DOUBLE_EQ(south.ues_served_mean, 1);
  EXPECT_DOUBLE_EQ(south.throughput_mean_mbps, 25);
  EXPECT_FALSE(south.delay_mean_ms.has_value());
  EXPECT_DOUBLE_EQ(south.worst_ue_mean_mbps.value(), 0);
  EXPECT_DOUBLE_EQ(south.jain_mean.value(), 0.5);
  EXPECT_FALSE(s[1].jain_mean.has_value());
  EXPECT_TRUE(std::isnan(s[1].throughput_ci95_mbps));  // one run
}

TEST(UavSummary, Renderings) {
  const std::vector<UavSummary> s = SummarizeUavs(UavRows());
  const std::string csv = FormatUavSummaryCsv(s);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scenario,positioner,uav,uav_name,runs,ues_served_mean,throughput_mean_mbps,"
            "throughput_ci95_mbps,delay_mean_ms,nlos_mean,worst_ue_mean_mbps,jain_mean");
  EXPECT_NE(csv.find("\ntwo,baseline,1,south,1,0,0,,,0,,\n"), std::string::npos) << csv;
  const nlohmann::json json = UavSummaryToJson(s);
  ASSERT_EQ(json.size(), 4u);
  EXPECT_EQ(json[3]["uav_name"], "south");
  EXPECT_EQ(json[3]["uav"], 1);
  EXPECT_TRUE(json[3]["delay_mean_ms"].is_null());
  EXPECT_EQ(json[3]["throughput_mean_mbps"], 25.0);
  const std::string text = FormatUavSummaryText(s);
  EXPECT_NE(text.find("two       rl          south     2         1.0        25.00"),
            std::string::npos)
      << text;
  EXPECT_NE(FormatUavSummaryMarkdown(s).find("| two | rl | north | 2 | 5.0 | 250.00 |"),
            std::string::npos);
  EXPECT_TRUE(SummarizeUavs({UavRows()[0]}).empty());  // one UAV only: no table
}

}  // namespace
}  // namespace rlpos
