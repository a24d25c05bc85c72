#include "sim/metrics_report.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>

namespace rlpos {
namespace {
std::string Fixed(double x, int decimals) {
  if (!std::isfinite(x)) return "-";
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
  out << "scenario " << scenario.name << ", UAV at (" << Fixed(m.position.x, 1) << ", "
      << Fixed(m.position.y, 1) << ", " << Fixed(m.position.z, 1) << "), RngRun " << m.run
      << ", window " << Fixed(m.window.start, 2) << "-" << Fixed(m.window.end, 2) << " s\n";
  out << "  aggregate throughput  " << Fixed(m.aggregate_throughput_mbps, 2) << " Mbit/s (demand "
      << Fixed(scenario.TotalDemandMbps(), 1) << ")\n";
  out << "  mean delay            " << Fixed(m.mean_delay_ms, 3) << " ms\n";
  out << "  packet loss           " << Fixed(m.loss_ratio * 100.0, 2) << " %\n";
  out << "  nLoS                  " << m.n_los << "/" << m.ues.size() << "\n";
  out << "  demands met (SNR)     " << m.demands_met << "/" << m.ues.size() << "\n";
  out << "  min SNR               " << Fixed(m.min_snr_db, 1) << " dB\n";
  out << Row("  %-10s %-4s %8s %9s %4s %7s %-4s %10s %10s %7s\n", "UE", "LoS", "SNR(dB)",
             "demand", "MCS", "minSNR", "met", "thr(Mbps)", "delay(ms)", "loss%");
  for (const auto& u : m.ues) {
    out << Row("  %-10s %-4s %8s %9s %4d %7s %-4s %10s %10s %7s\n", u.name.c_str(),
               u.los ? "yes" : "no", Fixed(u.snr_db, 1).c_str(), Fixed(u.demand_mbps, 1).c_str(),
               u.demand.required_mcs, Fixed(u.demand.min_snr_db, 0).c_str(),
               u.demand.met ? "yes" : "no", Fixed(u.throughput_mbps, 2).c_str(),
               Fixed(u.mean_delay_ms, 3).c_str(), Fixed(u.loss_ratio * 100.0, 2).c_str());
  }
}

}  // namespace rlpos
