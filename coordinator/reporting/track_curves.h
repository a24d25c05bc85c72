#pragma once
// The report's figures of track runs (issue: UEs that walk, UAVs that follow), kept as plain
// rows that the report writes to CSV and scripts/plot_campaign.py draws:
//  - per scenario and positioner, the distribution over the RngRuns of each run's time means:
//    the CDF of the reward, the CCDF of the throughput (as the paper draws throughput), the CDF
//    of the delay (packet level) and of the outage share;
//  - the time series: each interval's metrics averaged over the runs.
// Scenarios and positioners come in the order of the track summary (track_groups.h).
#include <string>
#include <vector>

#include "common/store/track_rows.h"

namespace rlpos {

struct TrackCurvePoint {
  std::string scenario, positioner;
  std::string metric;  // a key of kTrackMetrics
  bool above = false;  // CCDF: p = P(X > x); CDF: p = P(X <= x)
  double x = 0.0;
  double p = 0.0;
};

std::vector<TrackCurvePoint> TrackDistributions(const std::vector<TrackRunRow>& rows);
// Header "scenario,positioner,metric,p_is,x,p"; p_is is "above" (CCDF) or "at_most" (CDF).
std::string FormatTrackDistributionsCsv(const std::vector<TrackCurvePoint>& points);

// The rows of ResultsReader::TrackSeries in the summary's order of positioners.
std::vector<TrackSeriesRow> OrderTrackSeries(std::vector<TrackSeriesRow> rows);
// Header "scenario,positioner,interval,time_s,runs,scored,reward,throughput_mbps,delay_ms,
// los_share,demands_met_share" (delay empty where no run has one).
std::string FormatTrackSeriesCsv(const std::vector<TrackSeriesRow>& rows);

}  // namespace rlpos
