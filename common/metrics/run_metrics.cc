#include "common/metrics/run_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rlpos {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nlohmann::json UavToJson(const UavMetrics& u) {
  const Vec3& p = u.uav.position;
  nlohmann::json out = {
      {"name", u.uav.name}, {"position", {p.x, p.y, p.z}}, {"channel", u.uav.channel}};
  for (const auto& metric : kEvalMetrics) {
    if (metric.uav_count) {
      out[metric.uav_key] = u.*metric.uav_count;
    } else if (metric.uav_real) {
      out[metric.uav_key] = MetricJson(u.*metric.uav_real);
    }
  }
  return out;
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

namespace {

// The aggregates over the UEs `members` picks (all of them for the run, a UAV's for the UAV).
struct Aggregate {
  double throughput_mbps = 0.0, mean_delay_ms = kNaN, loss_ratio = kNaN;
  double worst_ue_throughput_mbps = kNaN, jain_fairness = kNaN, min_snr_db = kNaN;
  int n_los = 0, demands_met = 0, ues = 0;
};

template <typename Member>
Aggregate AggregateOf(MeasurementWindow window, const std::vector<FlowAccumulator>& flows,
                      const std::vector<UeMetrics>& ues, Member member) {
  Aggregate a;
  std::uint64_t bytes = 0, received = 0, sent = 0, delivered = 0;
  double delay_sum = 0.0;
  std::vector<double> throughputs;
  for (std::size_t i = 0; i < flows.size() && i < ues.size(); ++i) {
    if (!member(ues[i]))
      continue;
    const auto& f = flows[i];
    bytes += f.BytesInWindow();
    received += f.ReceivedInWindow();
    sent += f.SentInWindow();
    delivered += f.DeliveredOfSentInWindow();
    delay_sum += f.DelaySumS();
    a.n_los += ues[i].los ? 1 : 0;
    a.demands_met += ues[i].demand.met ? 1 : 0;
    a.min_snr_db = a.ues == 0 ? ues[i].snr_db : std::min(a.min_snr_db, ues[i].snr_db);
    throughputs.push_back(ues[i].throughput_mbps);
    ++a.ues;
  }
  if (!throughputs.empty())
    a.worst_ue_throughput_mbps = *std::min_element(throughputs.begin(), throughputs.end());
  a.jain_fairness = JainIndex(throughputs);
  a.throughput_mbps = bytes * 8.0 / window.Length() / 1e6;
  a.mean_delay_ms = received == 0 ? kNaN : delay_sum / received * 1e3;
  a.loss_ratio = sent == 0 ? kNaN : 1.0 - static_cast<double>(delivered) / sent;
  return a;
}

}  // namespace

RunMetrics Summarize(const std::vector<UavIdentity>& uavs, MeasurementWindow window,
                     std::uint64_t run, const std::vector<FlowAccumulator>& flows,
                     std::vector<UeMetrics> ues) {
  RunMetrics m;
  m.position = uavs.empty() ? Vec3{} : uavs.front().position;
  m.window = window;
  m.run = run;
  for (std::size_t i = 0; i < flows.size() && i < ues.size(); ++i) {
    ues[i].throughput_mbps = flows[i].ThroughputMbps();
    ues[i].mean_delay_ms = flows[i].MeanDelayMs();
    ues[i].loss_ratio = flows[i].LossRatio();
    ues[i].sent = flows[i].SentInWindow();
    ues[i].received = flows[i].ReceivedInWindow();
  }
  const Aggregate all = AggregateOf(window, flows, ues, [](const UeMetrics&) { return true; });
  m.aggregate_throughput_mbps = all.throughput_mbps;
  m.mean_delay_ms = all.mean_delay_ms;
  m.loss_ratio = all.loss_ratio;
  m.n_los = all.n_los;
  m.demands_met = all.demands_met;
  m.reward = kNaN;  // the packets do not give it: the evaluator adds it (null until then)
  m.min_snr_db = all.ues == 0 ? std::numeric_limits<double>::infinity() : all.min_snr_db;
  m.worst_ue_throughput_mbps = all.ues == 0 ? 0.0 : all.worst_ue_throughput_mbps;
  m.jain_fairness = all.jain_fairness;
  m.n_ues = static_cast<int>(ues.size());
  for (std::size_t u = 0; u < uavs.size(); ++u) {
    const int index = static_cast<int>(u);
    const Aggregate a =
        AggregateOf(window, flows, ues, [index](const UeMetrics& ue) { return ue.uav == index; });
    UavMetrics share;
    share.uav = uavs[u];
    share.ues_served = a.ues;
    share.throughput_mbps = a.throughput_mbps;
    share.mean_delay_ms = a.mean_delay_ms;
    share.loss_ratio = a.loss_ratio;
    share.n_los = a.n_los;
    share.worst_ue_throughput_mbps = a.worst_ue_throughput_mbps;
    share.jain_fairness = a.jain_fairness;
    m.uavs.push_back(share);
  }
  m.ues = std::move(ues);
  return m;
}

RunMetrics Summarize(const Vec3& position, MeasurementWindow window, std::uint64_t run,
                     const std::vector<FlowAccumulator>& flows, std::vector<UeMetrics> ues) {
  return Summarize({UavIdentity{"uav", position, 0}}, window, run, flows, std::move(ues));
}

nlohmann::json ToJson(const RunMetrics& m) {
  nlohmann::json ues = nlohmann::json::array();
  for (const auto& u : m.ues) {
    ues.push_back({{"name", u.name},
                   {"los", u.los},
                   {"snr_db", MetricJson(u.snr_db)},
                   {"demand_mbps", u.demand_mbps},
                   {"required_mcs", u.demand.required_mcs},
                   {"min_snr_db", MetricJson(u.demand.min_snr_db)},
                   {"demand_met", u.demand.met},
                   {"throughput_mbps", MetricJson(u.throughput_mbps)},
                   {"mean_delay_ms", MetricJson(u.mean_delay_ms)},
                   {"loss_ratio", MetricJson(u.loss_ratio)},
                   {"sent", u.sent},
                   {"received", u.received}});
  }
  nlohmann::json out = {{"position", {m.position.x, m.position.y, m.position.z}},
                        {"window_s", {m.window.start, m.window.end}},
                        {"run", m.run},
                        {"ues", ues}};
  for (const auto& metric : kEvalMetrics) {
    out[metric.key] =
        metric.IsCount() ? nlohmann::json(m.*metric.run_count) : MetricJson(m.*metric.run_real);
  }
  if (m.uavs.size() > 1) {
    nlohmann::json uavs = nlohmann::json::array();
    for (const auto& u : m.uavs)
      uavs.push_back(UavToJson(u));
    out["uavs"] = uavs;
    for (std::size_t i = 0; i < m.ues.size(); ++i)
      out["ues"][i]["uav"] = m.uavs.at(static_cast<std::size_t>(m.ues[i].uav)).uav.name;
  }
  return out;
}

nlohmann::json MetricJson(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

}  // namespace rlpos
