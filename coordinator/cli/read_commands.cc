// status, results, report: read the database (read-only; the coordinator may be running).
#include <chrono>
#include <iostream>
#include <thread>

#include "common/process/executable_path.h"
#include "common/process/stop_signal.h"
#include "common/process/wall_clock.h"
#include "common/store/results_reader.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"
#include "coordinator/cli/campaign_commands.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/optimality.h"
#include "coordinator/reporting/progress_text.h"
#include "coordinator/reporting/report_writer.h"
#include "coordinator/reporting/results_format.h"
#include "coordinator/reporting/scenario_maps.h"
#include "coordinator/reporting/track_summary.h"
#include "coordinator/reporting/uav_summary.h"

namespace rlpos {
namespace {

StoreOptions ReadOnly() {
  StoreOptions options;
  options.read_only = true;
  return options;
}

}  // namespace

int ShowStatus(const std::string& db, const std::string& campaign_id, bool watch, double period_s) {
  for (;;) {
    StoreDb opened(db, ReadOnly());
    ResultsReader store(opened);
    std::vector<CampaignProgress> campaigns;
    if (campaign_id.empty()) {
      campaigns = store.AllProgress();
    } else {
      campaigns.push_back(store.Progress(campaign_id));
    }
    std::vector<CampaignTiming> timings;
    for (const auto& c : campaigns)
      timings.push_back(store.Timing(c.campaign_id));
    std::cout << FormatStatus(campaigns, timings, store.ListWorkers(), WallClockSeconds());
    for (const auto& c : campaigns) {
      for (const auto& j : store.RunningJobs(c.campaign_id)) {
        std::cout << "  running: " << j.key << " #" << j.attempt << " on " << j.worker_id << " for "
                  << FormatDuration(WallClockSeconds() - j.started_at)
                  << (j.progress.empty() ? "" : ": " + j.progress) << "\n";
      }
      for (const auto& f : store.FailedJobs(c.campaign_id)) {
        std::cout << "  failed: " << f.key << " after " << f.attempts << " attempt(s): " << f.error
                  << "\n";
      }
      if (const auto builds = store.CampaignBuilds(c.campaign_id); builds.size() > 1) {
        std::cout << "  warning: results from " << builds.size() << " different builds:";
        for (const auto& b : builds)
          std::cout << "\n    " << b;
        std::cout << "\n";
      }
    }
    bool settled = true;
    for (const auto& c : campaigns)
      settled = settled && IsSettled(c);
    if (!watch || settled || StopRequested())
      return kExitOk;
    std::cout << std::flush;
    std::this_thread::sleep_for(std::chrono::duration<double>(period_s));
    std::cout << "\n";
  }
}

int ShowResults(const std::string& db, const std::string& campaign_id, const std::string& format,
                ResultsView view) {
  StoreDb opened(db, ReadOnly());
  ResultsReader store(opened);
  store.Progress(campaign_id);  // StoreError for an unknown campaign
  if (view == ResultsView::kTrack) {
    const auto tracks = SummarizeTracks(store.TrackRuns(campaign_id));
    if (format == "csv") {
      std::cout << FormatTrackSummaryCsv(tracks);
    } else if (format == "json") {
      std::cout << TrackSummaryToJson(tracks).dump(2) << "\n";
    } else {
      std::cout << FormatTrackSummaryText(tracks);
    }
    return kExitOk;
  }
  if (view == ResultsView::kOptimality) {
    const auto summary = SummarizeOptimality(store.Optimality(campaign_id));
    if (format == "csv") {
      std::cout << FormatOptimalitySummaryCsv(summary);
    } else if (format == "json") {
      std::cout << OptimalityToJson(summary).dump(2) << "\n";
    } else {
      std::cout << FormatOptimalityText(summary);
    }
    return kExitOk;
  }
  if (view == ResultsView::kPerUav) {
    const auto uavs = SummarizeUavs(store.UavMetrics(campaign_id));
    if (format == "csv") {
      std::cout << FormatUavSummaryCsv(uavs);
    } else if (format == "json") {
      std::cout << UavSummaryToJson(uavs).dump(2) << "\n";
    } else {
      std::cout << FormatUavSummaryText(uavs);
    }
    return kExitOk;
  }
  if (format == "csv") {
    std::cout << FormatSummaryCsv(SummarizeCampaign(store, campaign_id));
  } else if (format == "json") {
    std::cout << SummaryToJson(SummarizeCampaign(store, campaign_id)).dump(2) << "\n";
  } else {
    std::cout << ResultsTables(store, campaign_id);
  }
  return kExitOk;
}

std::string ResultsTables(ResultsReader& store, const std::string& campaign_id) {
  const auto summary = SummarizeCampaign(store, campaign_id);
  const auto tracks = SummarizeTracks(store.TrackRuns(campaign_id));
  // A campaign of track runs only has no eval summary to show.
  std::string out = summary.empty() && !tracks.empty() ? "" : FormatSummaryText(summary);
  const auto uavs = SummarizeUavs(store.UavMetrics(campaign_id));
  if (!uavs.empty())
    out += "\nper UAV:\n" + FormatUavSummaryText(uavs);
  const auto optimality = SummarizeOptimality(store.Optimality(campaign_id));
  if (!optimality.empty())
    out += "\noptimality (each placement's reward / the oracle's):\n" +
           FormatOptimalityText(optimality);
  if (!tracks.empty())
    out += std::string(out.empty() ? "" : "\n") +
           "track runs (means over the RngRuns of each run's time mean and P5):\n" +
           FormatTrackSummaryText(tracks);
  return out;
}

int WriteCampaignReport(const std::string& db, const std::string& campaign_id,
                        const std::string& out_dir) {
  StoreDb opened(db, ReadOnly());
  ResultsReader store(opened);
  ReportOptions options;
  options.plot_script = DefaultPlotScript(ExecutableDir());
  options.render_program = DefaultRenderProgram(ExecutableDir());
  const ReportResult result = WriteReport(store, campaign_id, out_dir, options);
  for (const auto& w : result.warnings)
    std::cerr << "rlpos-campaign: warning: " << w << "\n";
  for (const auto& f : result.files)
    std::cout << f << "\n";
  return kExitOk;
}

}  // namespace rlpos
