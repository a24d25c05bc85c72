#include "worker/programs/rlpos_sim/metrics_report.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>

#include "common/scenario/number_text.h"

namespace rlpos {
namespace {
std::string Fixed(double x, int decimals) {
  if (!std::isfinite(x))
    return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  return buffer;
}
std::string Row(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Row(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}
}  // namespace

void PrintMetricsTable(std::ostream& out, const Scenario& scenario, const RunMetrics& m) {
  const bool several = m.uavs.size() > 1;
  Placement placement;
  for (const auto& u : m.uavs)
    placement.push_back(u.uav.position);
  if (!several)
    placement = {m.position};
  out << "scenario " << scenario.name << (several ? ", UAVs at " : ", UAV at ")
      << DescribePlacement(placement) << ", RngRun " << m.run << ", window "
      << Fixed(m.window.start, 2) << "-" << Fixed(m.window.end, 2) << " s\n";
  out << "  aggregate throughput  " << Fixed(m.aggregate_throughput_mbps, 2) << " Mbit/s (demand "
      << Fixed(scenario.TotalDemandMbps(), 1) << ")\n";
  out << "  mean delay            " << Fixed(m.mean_delay_ms, 3) << " ms\n";
  out << "  packet loss           " << Fixed(m.loss_ratio * 100.0, 2) << " %\n";
  out << "  nLoS                  " << m.n_los << "/" << m.ues.size() << "\n";
  out << "  demands met (SNR)     " << m.demands_met << "/" << m.ues.size() << "\n";
  out << "  min SNR               " << Fixed(m.min_snr_db, 1) << " dB\n";
  if (several) {
    out << Row("  %-10s %7s %4s %10s %10s %7s %5s %10s %6s\n", "UAV", "channel", "UEs", "thr(Mbps)",
               "delay(ms)", "loss%", "nLoS", "worst UE", "Jain");
    for (const auto& u : m.uavs) {
      out << Row("  %-10s %7d %4d %10s %10s %7s %5d %10s %6s\n", u.uav.name.c_str(), u.uav.channel,
                 u.ues_served, Fixed(u.throughput_mbps, 2).c_str(),
                 Fixed(u.mean_delay_ms, 3).c_str(), Fixed(u.loss_ratio * 100.0, 2).c_str(), u.n_los,
                 Fixed(u.worst_ue_throughput_mbps, 2).c_str(), Fixed(u.jain_fairness, 3).c_str());
    }
  }
  std::string header =
      Row("  %-10s %-4s %8s %9s %4s %7s %-4s %10s %10s %7s\n", "UE", "LoS", "SNR(dB)", "demand",
          "MCS", "minSNR", "met", "thr(Mbps)", "delay(ms)", "loss%");
  if (several) {
    header.pop_back();
    header += "  UAV\n";
  }
  out << header;
  for (const auto& u : m.ues) {
    std::string row =
        Row("  %-10s %-4s %8s %9s %4d %7s %-4s %10s %10s %7s\n", u.name.c_str(),
            u.los ? "yes" : "no", Fixed(u.snr_db, 1).c_str(), Fixed(u.demand_mbps, 1).c_str(),
            u.demand.required_mcs, Fixed(u.demand.min_snr_db, 0).c_str(),
            u.demand.met ? "yes" : "no", Fixed(u.throughput_mbps, 2).c_str(),
            Fixed(u.mean_delay_ms, 3).c_str(), Fixed(u.loss_ratio * 100.0, 2).c_str());
    if (several) {  // the UE's UAV closes its row
      row.pop_back();
      row += "  " + m.uavs[static_cast<std::size_t>(u.uav)].uav.name + "\n";
    }
    out << row;
  }
}

}  // namespace rlpos
