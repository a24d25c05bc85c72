#include "metrics/run_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rlpos {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// JSON has no NaN: an undefined metric (no packet) is written as null.
nlohmann::json Number(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}
}  // namespace

void FlowAccumulator::OnSent(double sent_at) {
  if (window_.Holds(sent_at))
    ++sent_;
}

void FlowAccumulator::OnReceived(double sent_at, double received_at, std::uint64_t bytes) {
  if (window_.Holds(sent_at))
    ++delivered_of_sent_;
  if (!window_.Holds(received_at))
    return;
  ++received_packets_;
  received_bytes_ += bytes;
  delay_sum_s_ += received_at - sent_at;
}

double FlowAccumulator::ThroughputMbps() const {
  return received_bytes_ * 8.0 / window_.Length() / 1e6;
}

double FlowAccumulator::MeanDelayMs() const {
  return received_packets_ == 0 ? kNaN : delay_sum_s_ / received_packets_ * 1e3;
}

double FlowAccumulator::LossRatio() const {
  return sent_ == 0 ? kNaN : 1.0 - static_cast<double>(delivered_of_sent_) / sent_;
}

DemandCheck CheckDemand(const PhyProfile& phy, double demand_mbps, double snr_db) {
  DemandCheck check;
  check.required_mcs = RequiredMcs(phy, demand_mbps);
  if (check.required_mcs < 0) {
    check.min_snr_db = std::numeric_limits<double>::infinity();
    return check;
  }
  check.min_snr_db = McsMinSnrDb(check.required_mcs);
  check.met = snr_db >= check.min_snr_db;
  return check;
}

double JainIndex(const std::vector<double>& values) {
  double sum = 0.0, squares = 0.0;
  for (double v : values) {
    sum += v;
    squares += v * v;
  }
  return sum > 0.0 ? sum * sum / (static_cast<double>(values.size()) * squares) : kNaN;
}

RunMetrics Summarize(const Vec3& position, MeasurementWindow window, std::uint64_t run,
                     const std::vector<FlowAccumulator>& flows, std::vector<UeMetrics> ues) {
  RunMetrics m;
  m.position = position;
  m.window = window;
  m.run = run;
  std::uint64_t bytes = 0, received = 0, sent = 0, delivered = 0;
  double delay_sum = 0.0;
  m.min_snr_db = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < flows.size() && i < ues.size(); ++i) {
    const auto& f = flows[i];
    auto& ue = ues[i];
    ue.throughput_mbps = f.ThroughputMbps();
    ue.mean_delay_ms = f.MeanDelayMs();
    ue.loss_ratio = f.LossRatio();
    ue.sent = f.SentInWindow();
    ue.received = f.ReceivedInWindow();
    bytes += f.BytesInWindow();
    received += f.ReceivedInWindow();
    sent += f.SentInWindow();
    delivered += f.DeliveredOfSentInWindow();
    delay_sum += f.DelaySumS();
    m.n_los += ue.los ? 1 : 0;
    m.demands_met += ue.demand.met ? 1 : 0;
    m.min_snr_db = std::min(m.min_snr_db, ue.snr_db);
  }
  std::vector<double> throughputs;
  for (const auto& ue : ues)
    throughputs.push_back(ue.throughput_mbps);
  m.worst_ue_throughput_mbps =
      throughputs.empty() ? 0.0 : *std::min_element(throughputs.begin(), throughputs.end());
  m.jain_fairness = JainIndex(throughputs);
  m.aggregate_throughput_mbps = bytes * 8.0 / window.Length() / 1e6;
  m.mean_delay_ms = received == 0 ? kNaN : delay_sum / received * 1e3;
  m.loss_ratio = sent == 0 ? kNaN : 1.0 - static_cast<double>(delivered) / sent;
  m.ues = std::move(ues);
  return m;
}

nlohmann::json ToJson(const RunMetrics& m) {
  nlohmann::json ues = nlohmann::json::array();
  for (const auto& u : m.ues) {
    ues.push_back({{"name", u.name},
                   {"los", u.los},
                   {"snr_db", Number(u.snr_db)},
                   {"demand_mbps", u.demand_mbps},
                   {"required_mcs", u.demand.required_mcs},
                   {"min_snr_db", Number(u.demand.min_snr_db)},
                   {"demand_met", u.demand.met},
                   {"throughput_mbps", Number(u.throughput_mbps)},
                   {"mean_delay_ms", Number(u.mean_delay_ms)},
                   {"loss_ratio", Number(u.loss_ratio)},
                   {"sent", u.sent},
                   {"received", u.received}});
  }
  return {{"position", {m.position.x, m.position.y, m.position.z}},
          {"window_s", {m.window.start, m.window.end}},
          {"run", m.run},
          {"aggregate_throughput_mbps", Number(m.aggregate_throughput_mbps)},
          {"mean_delay_ms", Number(m.mean_delay_ms)},
          {"loss_ratio", Number(m.loss_ratio)},
          {"n_los", m.n_los},
          {"n_ues", m.ues.size()},
          {"demands_met", m.demands_met},
          {"min_snr_db", Number(m.min_snr_db)},
          {"worst_ue_throughput_mbps", Number(m.worst_ue_throughput_mbps)},
          {"jain_fairness", Number(m.jain_fairness)},
          {"ues", ues}};
}

}  // namespace rlpos
