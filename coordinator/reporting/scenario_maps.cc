#include "coordinator/reporting/scenario_maps.h"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/campaign/campaign_spec.h"
#include "common/files/atomic_file.h"
#include "common/hash/sha256.h"
#include "common/process/child_process.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"
#include "common/store/artifact_files.h"
#include "common/wire/identifiers.h"
#include "coordinator/reporting/run_groups.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;

// The campaign's scenarios as its jobs ran them: name -> document with its overrides applied.
std::vector<std::pair<std::string, nlohmann::json>> CampaignScenarios(ResultsReader& store,
                                                                      const std::string& id) {
  std::vector<std::pair<std::string, nlohmann::json>> out;
  const auto part = store.CampaignSpecPart(id, "scenarios");
  if (!part || !part->contains("scenarios") || !(*part)["scenarios"].is_array())
    return out;
  for (const auto& entry : (*part)["scenarios"]) {
    try {
      const nlohmann::json document = StatedScenarioDocument(entry);
      out.emplace_back(document.value("name", std::string("scenario")), document);
    } catch (const std::exception&) {
      // A document that does not parse ran no job either: it has no map.
    }
  }
  return out;
}

// scenario -> label -> placement of the label's eval with the lowest RngRun.
using Placements = std::map<std::string, std::map<std::string, Placement>>;

Placements FirstRunPlacements(ResultsReader& store, const std::string& id) {
  Placements out;
  std::map<std::pair<std::string, std::string>, std::string> first_job;
  // Rows come by scenario, label, rng_run, then UAV: the first job seen is the lowest run.
  for (const UavMetricRow& row : store.UavMetrics(id)) {
    const auto key = std::make_pair(row.scenario, row.label);
    const auto seen = first_job.emplace(key, row.job_id).first;
    if (seen->second == row.job_id)
      out[row.scenario][row.label].push_back({row.x, row.y, row.z});
  }
  return out;
}

// LABEL=x,y,z;x,y,z as rlpos-sim render --placement takes it.
std::string PlacementArgument(const std::string& label, const Placement& placement) {
  std::string text = label + "=";
  for (std::size_t u = 0; u < placement.size(); ++u)
    text += (u ? ";" : "") + FormatPosition(placement[u]);
  return text;
}

std::string ReadWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read it");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The trajectory.csv of the train job behind `label`, checked against its sha256, copied to
// `target`. The file must lie inside the artifacts folder (ResolveArtifactFile).
bool CopyFlight(ResultsReader& store, const std::string& id, const std::string& scenario,
                const std::string& label, const fs::path& target,
                std::vector<std::string>& warnings) {
  for (const ArtifactRecord& a : store.Artifacts(id)) {
    if (a.name != "trajectory.csv" || a.scenario != scenario || a.label != label)
      continue;
    try {
      const std::string data = ReadWhole(ResolveArtifactFile(ArtifactsDirOf(store.file()), a.path));
      if (Sha256Hex(data) != a.sha256)
        throw std::runtime_error("it does not match the sha256 the database holds");
      WriteFileAtomically(target.string(), data);
      return true;
    } catch (const std::exception& e) {
      warnings.push_back("map of scenario " + wire::Printable(scenario) + ": the rl flight of " +
                         wire::Printable(label) + " is not drawn: " + e.what());
      return false;
    }
  }
  return false;
}

// A folder of the report's own, removed with everything in it when the maps are drawn.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "rlpos-report-maps-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error("cannot create a temporary folder for the maps");
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string FirstLine(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return wire::Printable(line, 200);
}

}  // namespace

ScenarioMapsOutcome RenderScenarioMaps(ResultsReader& store, const std::string& campaign_id,
                                       const std::string& render_program,
                                       const std::string& out_dir) {
  ScenarioMapsOutcome outcome;
  const auto scenarios = CampaignScenarios(store, campaign_id);
  const Placements placements = FirstRunPlacements(store, campaign_id);
  const TempFolder temp;
  for (std::size_t k = 0; k < scenarios.size(); ++k) {
    const auto& [name, document] = scenarios[k];
    ScenarioMap map{name, "map_" + std::to_string(k + 1) + ".png", {}, false};
    const fs::path scenario_file = temp.path() / ("scenario_" + std::to_string(k + 1) + ".json");
    WriteFileAtomically(scenario_file.string(), document.dump(2));
    std::vector<std::string> argv{render_program, "render", scenario_file.string()};
    const auto found = placements.find(name);
    if (found != placements.end()) {
      std::vector<std::string> labels;
      for (const auto& entry : found->second)
        labels.push_back(entry.first);
      std::sort(labels.begin(), labels.end(), ReportLabelLess);
      for (const auto& label : labels) {
        argv.push_back("--placement");
        argv.push_back(PlacementArgument(label, found->second.at(label)));
      }
      map.labels = labels;
      // The flight of the first rl label (the first seed's, of the scenario's own algorithm).
      for (const auto& label : labels) {
        if (label.rfind("rl", 0) != 0)
          continue;
        const fs::path flight = temp.path() / ("trajectory_" + std::to_string(k + 1) + ".csv");
        map.flight = CopyFlight(store, campaign_id, name, label, flight, outcome.warnings);
        if (map.flight)
          argv.insert(argv.end(), {"--trajectory", flight.string()});
        break;
      }
    }
    const std::string out = (fs::path(out_dir) / map.file).string();
    argv.insert(argv.end(), {"--out", out});
    const ProcessResult run = RunProcess(argv);
    if (!run.started || ShellStatus(run.exit) != 0) {
      outcome.warnings.push_back("map of scenario " + wire::Printable(name) +
                                 " not drawn: " + FirstLine(run.output));
      continue;
    }
    outcome.files.push_back(out);
    outcome.maps.push_back(std::move(map));
  }
  return outcome;
}

std::string FormatMapsMarkdown(const std::vector<ScenarioMap>& maps) {
  if (maps.empty())
    return "";
  std::string md =
      "\n## Maps\n\nEach positioner's placement (that of its eval with the lowest RngRun: every "
      "run of a label evaluates the same placement), the UEs with their demand in Mbit/s; "
      "drawn by `rlpos-sim render`.\n";
  for (const ScenarioMap& m : maps) {
    md += "\n### Scenario " + m.scenario + "\n\n![Scenario " + m.scenario + "](" + m.file + ")\n";
    if (m.labels.empty())
      md += "\nNo eval has succeeded yet: the baseline placement.\n";
    if (m.flight)
      md += "\nThe rl flight: the last greedy evaluation episode of its train job.\n";
  }
  return md;
}

std::string DefaultRenderProgram(const std::string& exe_dir) {
  return (fs::path(exe_dir) / "rlpos-sim").string();
}

}  // namespace rlpos
