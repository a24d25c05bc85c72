#include "coordinator/reporting/report_writer.h"

#include <filesystem>

#include "common/files/atomic_file.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/distribution_curves.h"
#include "coordinator/reporting/learning_curves.h"
#include "coordinator/reporting/optimality.h"
#include "coordinator/reporting/plot_script.h"
#include "coordinator/reporting/report_markdown.h"
#include "coordinator/reporting/results_format.h"
#include "coordinator/reporting/scenario_maps.h"
#include "coordinator/reporting/track_curves.h"
#include "coordinator/reporting/track_summary.h"
#include "coordinator/reporting/uav_summary.h"

namespace rlpos {
namespace {

// The maps of the campaign's scenarios; returns their Markdown section.
std::string RenderMaps(ResultsReader& store, const std::string& campaign_id,
                       const std::string& out_dir, const std::string& render_program,
                       ReportResult& result) {
  if (render_program.empty())
    return "";
  if (!std::filesystem::exists(render_program)) {
    result.warnings.push_back("no maps: " + render_program + " not found");
    return "";
  }
  try {
    const ScenarioMapsOutcome maps =
        RenderScenarioMaps(store, campaign_id, render_program, out_dir);
    result.files.insert(result.files.end(), maps.files.begin(), maps.files.end());
    result.warnings.insert(result.warnings.end(), maps.warnings.begin(), maps.warnings.end());
    return FormatMapsMarkdown(maps.maps);
  } catch (const std::exception& e) {
    // Maps are best effort, like the plots: the tables are the report.
    result.warnings.push_back(std::string("no maps: ") + e.what());
    return "";
  }
}

}  // namespace

ReportResult WriteReport(ResultsReader& store, const std::string& campaign_id,
                         const std::string& out_dir, const ReportOptions& options) {
  const CampaignProgress progress = store.Progress(campaign_id);  // StoreError when unknown
  const std::vector<MetricRow> rows = store.Metrics(campaign_id);
  const std::vector<PositionerSummary> summary = SummarizeRuns(rows);
  const std::vector<UavSummary> uavs = SummarizeUavs(store.UavMetrics(campaign_id));
  const std::vector<TrackRunRow> track_runs = store.TrackRuns(campaign_id);
  const std::vector<TrackSummary> tracks = SummarizeTracks(track_runs);
  const std::vector<CurvePoint> throughput = ThroughputCcdf(rows);
  const std::vector<CurvePoint> delay = DelayCdf(rows);
  const std::vector<OptimalityRow> optimality = store.Optimality(campaign_id);
  const std::vector<OptimalitySummary> optimality_summary = SummarizeOptimality(optimality);

  CreateReportDir(out_dir);
  ReportResult result;
  const auto write = [&](const std::string& name, const std::string& content) {
    const std::string path = (std::filesystem::path(out_dir) / name).string();
    WriteFileAtomically(path, content);
    result.files.push_back(path);
    return path;
  };
  write("summary.csv", FormatSummaryCsv(summary));
  if (!uavs.empty())
    write("uav_summary.csv", FormatUavSummaryCsv(uavs));
  if (!tracks.empty())
    write("track_summary.csv", FormatTrackSummaryCsv(tracks));
  std::string markdown = FormatReportMarkdown(progress, summary, uavs) +
                         FormatOptimalitySection(optimality) + FormatTrackSummaryMarkdown(tracks);
  const auto builds = store.CampaignBuilds(campaign_id);
  if (builds.size() > 1) {
    std::string list;
    for (const auto& b : builds)
      list += (list.empty() ? "" : "; ") + b;
    const std::string warning =
        "the results come from " + std::to_string(builds.size()) + " different builds: " + list;
    result.warnings.push_back(warning);
    markdown += "\n**Warning:** " + warning + ".\n";
  }
  markdown += RenderMaps(store, campaign_id, out_dir, options.render_program, result);
  write("summary.md", markdown);
  const std::string throughput_csv =
      write("throughput_ccdf.csv", FormatThroughputCcdfCsv(throughput));
  const std::string delay_csv = write("delay_cdf.csv", FormatDelayCdfCsv(delay));
  const std::vector<LearningCurvePoint> learning =
      ReadLearningCurves(store, campaign_id, result.warnings);
  const std::string learning_csv =
      learning.empty() ? "" : write("learning_curves.csv", FormatLearningCurvesCsv(learning));
  std::string optimality_csv;
  if (!optimality_summary.empty()) {
    write("optimality.csv", FormatOptimalityRowsCsv(optimality));
    write("optimality_summary.csv", FormatOptimalitySummaryCsv(optimality_summary));
    optimality_csv = write("optimality_cdf.csv", FormatOptimalityCdfCsv(optimality));
  }

  std::string track_distributions_csv, track_series_csv;
  if (!tracks.empty()) {
    track_distributions_csv = write("track_distributions.csv",
                                    FormatTrackDistributionsCsv(TrackDistributions(track_runs)));
    track_series_csv = write(
        "track_series.csv", FormatTrackSeriesCsv(OrderTrackSeries(store.TrackSeries(campaign_id))));
  }

  if (options.plot_script.empty() ||
      (throughput.empty() && delay.empty() && learning.empty() && tracks.empty()))
    return result;
  const PlotOutcome plots = RenderPlots(
      {options.plot_script, options.python, throughput_csv, delay_csv, learning_csv, optimality_csv,
       track_distributions_csv, track_series_csv, out_dir, progress.name});
  result.files.insert(result.files.end(), plots.files.begin(), plots.files.end());
  result.warnings.insert(result.warnings.end(), plots.warnings.begin(), plots.warnings.end());
  return result;
}

std::string DefaultPlotScript(const std::string& exe_dir) {
  return (std::filesystem::path(exe_dir) / ".." / "share" / "rlpos" / "plot_campaign.py").string();
}

}  // namespace rlpos
