#include "coordinator/reporting/progress_text.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rlpos {

std::optional<double> EstimateRemainingSeconds(const CampaignProgress& progress,
                                               const CampaignTiming& timing, double now) {
  const int done = progress.succeeded + progress.failed + progress.cancelled;
  const int left = progress.total - done;
  if (done == 0 || left <= 0 || !timing.first_started_at)
    return std::nullopt;
  const double elapsed = now - *timing.first_started_at;
  if (elapsed <= 0)
    return std::nullopt;
  return elapsed / done * left;
}

bool IsSettled(const CampaignProgress& progress) {
  return progress.pending + progress.ready + progress.running == 0;
}

std::string ProgressLine(const CampaignProgress& progress, std::optional<double> eta_s,
                         int bar_width) {
  const int done = progress.succeeded + progress.failed + progress.cancelled;
  const int filled = progress.total > 0 ? bar_width * done / progress.total : bar_width;
  std::ostringstream line;
  line << '[' << std::string(filled, '#') << std::string(bar_width - filled, '.') << "] " << done
       << '/' << progress.total << "  running " << progress.running;
  if (progress.failed > 0)
    line << "  failed " << progress.failed;
  if (progress.cancelled > 0)
    line << "  cancelled " << progress.cancelled;
  if (eta_s)
    line << "  ETA " << FormatDuration(*eta_s);
  return line.str();
}

std::string FormatStatus(const std::vector<CampaignProgress>& campaigns,
                         const std::vector<CampaignTiming>& timings,
                         const std::vector<WorkerRecord>& workers, double now) {
  std::ostringstream out;
  if (campaigns.empty())
    out << "no campaigns\n";
  for (std::size_t i = 0; i < campaigns.size(); ++i) {
    const auto& p = campaigns[i];
    out << p.campaign_id << "  " << p.name << "  " << p.state << "\n";
    out << "  jobs: " << p.total << " total, " << p.pending << " pending, " << p.ready << " ready, "
        << p.running << " running, " << p.succeeded << " succeeded";
    if (p.cached > 0)
      out << " (" << p.cached << " from the cache)";
    out << ", " << p.failed << " failed, " << p.cancelled << " cancelled\n";
    const auto eta =
        i < timings.size() ? EstimateRemainingSeconds(p, timings[i], now) : std::optional<double>{};
    out << "  " << ProgressLine(p, IsSettled(p) ? std::nullopt : eta) << "\n";
    if (IsSettled(p) && i < timings.size() && timings[i].first_started_at &&
        timings[i].last_finished_at) {
      out << "  ran for "
          << FormatDuration(*timings[i].last_finished_at - *timings[i].first_started_at) << "\n";
    }
  }
  int alive = 0, slots = 0, busy = 0;
  for (const auto& w : workers) {
    if (w.state != "alive")
      continue;
    ++alive;
    slots += w.slots;
    busy += w.busy;
  }
  out << "workers: " << alive << " alive (" << busy << "/" << slots << " slots busy)";
  if (workers.size() > static_cast<std::size_t>(alive)) {
    out << ", " << workers.size() - alive << " gone";
  }
  out << "\n";
  for (const auto& w : workers) {
    if (w.state != "alive")
      continue;
    out << "  " << w.id << "  " << w.host << "  pid " << w.pid << "  " << w.busy << "/" << w.slots
        << " busy\n";
  }
  return out.str();
}

}  // namespace rlpos
