#pragma once
// `rlpos-campaign report`: everything about one campaign in one folder (summary in CSV and
// Markdown, the curve data, the plots), so a campaign's results can be read, shared and plotted
// without SQL. The CSV and Markdown files are always written; plots are best effort.
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

struct ReportOptions {
  std::string plot_script;  // plot_campaign.py (see DefaultPlotScript); empty: no plots
  std::string python;       // interpreter for it; empty: "python3", then /usr/bin/python3
  // rlpos-sim, which draws a map per scenario (see DefaultRenderProgram); empty: no maps
  std::string render_program;
};

struct ReportResult {
  std::vector<std::string> files;     // paths written, in the order written
  std::vector<std::string> warnings;  // e.g. why the plots are missing
};

// Writes into `out_dir` (created if missing; files replaced atomically): summary.csv,
// summary.md, throughput_ccdf.csv, delay_cdf.csv, learning_curves.csv (when train jobs sent
// their curves home), optimality.csv, optimality_summary.csv and optimality_cdf.csv (when a
// scenario has rl and oracle rewards), the maps (map_<k>.png, scenario_maps.h), then the PNGs of
// the plot script. Throws StoreError for an unknown campaign, std::runtime_error naming the path
// when a file or the folder cannot be written. A plot failure is a warning, not an error.
ReportResult WriteReport(ResultsReader& store, const std::string& campaign_id,
                         const std::string& out_dir, const ReportOptions& options = {});

// Where the build and install put the plot script relative to the folder of the rlpos
// binaries: <exe_dir>/../share/rlpos/plot_campaign.py.
std::string DefaultPlotScript(const std::string& exe_dir);

}  // namespace rlpos
