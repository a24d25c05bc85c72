#pragma once
// The report's figures are drawn by scripts/plot_campaign.py (Python 3 + matplotlib) from the
// curve CSVs, because C++ has no plotting library worth the dependency. Plots are optional: a
// missing script, interpreter or matplotlib is reported as a warning, never thrown.
#include <string>
#include <vector>

namespace rlpos {

struct PlotRequest {
  std::string script;                   // plot_campaign.py
  std::string python;                   // interpreter; empty: "python3", then /usr/bin/python3
  std::string throughput_csv;           // FormatThroughputCcdfCsv output
  std::string delay_csv;                // FormatDelayCdfCsv output
  std::string learning_csv;             // FormatLearningCurvesCsv output; empty: none
  std::string optimality_csv;           // FormatOptimalityCdfCsv output; empty: none
  std::string track_distributions_csv;  // FormatTrackDistributionsCsv output; empty: none
  std::string track_series_csv;         // FormatTrackSeriesCsv output; empty: none
  std::string out_dir;                  // where the PNGs go
  std::string title;                    // e.g. the campaign name
};

struct PlotOutcome {
  std::vector<std::string> files;     // PNGs the script wrote
  std::vector<std::string> warnings;  // why plots are missing, if they are
};

// Runs the script with each interpreter in turn until one has matplotlib.
PlotOutcome RenderPlots(const PlotRequest& request);

}  // namespace rlpos
