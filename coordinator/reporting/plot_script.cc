#include "coordinator/reporting/plot_script.h"

#include <filesystem>
#include <sstream>
#include <utility>

#include "common/process/child_process.h"

namespace rlpos {
namespace {

// plot_campaign.py's exit status when matplotlib cannot be imported.
constexpr int kNoMatplotlib = 3;
constexpr std::size_t kMaxDetail = 600;

std::string Trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  if (text.size() > kMaxDetail)
    text = "..." + text.substr(text.size() - kMaxDetail);
  for (char& c : text) {
    if (c == '\n')
      c = ' ';
  }
  return text;
}

}  // namespace

PlotOutcome RenderPlots(const PlotRequest& request) {
  PlotOutcome outcome;
  std::error_code error;
  if (!std::filesystem::is_regular_file(request.script, error)) {
    outcome.warnings.push_back("plots not drawn: plot script " + request.script + " not found");
    return outcome;
  }
  const std::vector<std::string> interpreters =
      request.python.empty() ? std::vector<std::string>{"python3", "/usr/bin/python3"}
                             : std::vector<std::string>{request.python};
  std::vector<std::string> failures;
  for (const auto& python : interpreters) {
    std::vector<std::string> argv{
        python,        request.script,    "--throughput-ccdf", request.throughput_csv,
        "--delay-cdf", request.delay_csv, "--out-dir",         request.out_dir,
        "--title",     request.title};
    if (!request.learning_csv.empty()) {
      argv.push_back("--learning-curves");
      argv.push_back(request.learning_csv);
    }
    const std::pair<const char*, const std::string*> optional_csvs[] = {
        {"--optimality-cdf", &request.optimality_csv},
        {"--track-distributions", &request.track_distributions_csv},
        {"--track-series", &request.track_series_csv}};
    for (const auto& [flag, csv] : optional_csvs) {
      if (!csv->empty()) {
        argv.push_back(flag);
        argv.push_back(*csv);
      }
    }
    const ProcessResult run = RunProcess(argv);
    std::istringstream lines(run.output);
    std::string line;
    std::string other;
    while (std::getline(lines, line)) {
      if (line.rfind("wrote ", 0) == 0) {
        outcome.files.push_back(line.substr(6));
      } else {
        other += line + "\n";
      }
    }
    const int status = ShellStatus(run.exit);
    if (run.started && status == 0)
      return outcome;
    failures.push_back(python + ": " +
                       (run.started ? "exit status " + std::to_string(status) + ": "
                                    : std::string("cannot run: ")) +
                       Trimmed(other));
    // Another interpreter may help only when this one could not run or lacks matplotlib.
    if (run.started && status != kNoMatplotlib)
      break;
  }
  std::string warning = "plots not drawn by " + request.script + ": ";
  for (std::size_t i = 0; i < failures.size(); ++i)
    warning += (i > 0 ? "; " : "") + failures[i];
  outcome.warnings.push_back(warning);
  return outcome;
}

}  // namespace rlpos
