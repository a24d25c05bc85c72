#include "gym/analytic_evaluator.h"

#include "environment/uav_network.h"
#include "metrics/airtime_model.h"
#include "metrics/mcs_table.h"
#include "metrics/run_metrics.h"

namespace rlpos {

AnalyticEvaluator::AnalyticEvaluator(const Scenario& scenario)
    : scenario_(scenario),
      network_(std::make_unique<UavNetwork>(scenario, scenario.uav.initial)),
      thresholds_db_(network_->McsSnrThresholdsDb()) {}

AnalyticEvaluator::~AnalyticEvaluator() = default;

StepInfo AnalyticEvaluator::Evaluate(const Vec3& position) {
  network_->SetUavPosition(position);
  const auto links = network_->Links();
  const WifiSpec& w = scenario_.wifi;
  const PhyProfile phy{w.standard, w.width_mhz, w.guard_interval_ns, w.spatial_streams};
  StepInfo info;
  info.position = position;
  std::vector<AirtimeLink> airtime(links.size());
  const int mpdu_bytes = MpduBytes(scenario_.traffic.packet_size);
  for (std::size_t i = 0; i < links.size(); ++i) {
    info.n_los += links[i].los ? 1 : 0;
    info.snr_db.push_back(links[i].snr_db);
    info.demands_met += CheckDemand(phy, scenario_.ues[i].demand_mbps, links[i].snr_db).met;
    int mcs = -1;
    while (mcs + 1 < static_cast<int>(thresholds_db_.size()) &&
           links[i].snr_db >= thresholds_db_[mcs + 1]) {
      ++mcs;
    }
    airtime[i].demand_mbps = scenario_.ues[i].demand_mbps;
    if (mcs >= 0) {
      // IdealWifiManager's thresholds only bound the bit error rate: near a threshold a
      // 1.4 kB MPDU still fails often enough that retransmissions eat a visible share.
      airtime[i].phy_rate_mbps = McsDataRateMbps(phy, mcs);
      airtime[i].mpdu_success = network_->MpduSuccessRate(mcs, links[i].snr_db, mpdu_bytes);
    }
  }
  const AirtimeEstimate estimate =
      EstimateAirtimeThroughput(airtime, scenario_.traffic.packet_size);
  info.throughput_mbps = estimate.aggregate_mbps;
  ue_throughput_ = estimate.throughput_mbps;
  return info;
}

}  // namespace rlpos
