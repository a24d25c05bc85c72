#include "worker/programs/rlpos_sim/render_command.h"

#include <iostream>

#include "common/config/config_error.h"
#include "common/files/atomic_file.h"
#include "common/mobility/ue_trajectories.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/map/map_links.h"
#include "worker/map/map_render.h"
#include "worker/map/trajectory_csv.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {
namespace {

constexpr std::size_t kMaxLabelLength = 40;

// A JSON [x, y, z] of `what`; throws ConfigError.
Vec3 PositionOf(const nlohmann::json& p, const std::string& what) {
  if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
    throw ConfigError("--result", what + " is not [x, y, z]: " + p.dump());
  return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}

// The positions of a result JSON: "positions" (position and train with several UAVs, train
// always), "uavs"[].position (eval with several UAVs), else "position" (the first UAV's).
Placement ResultPositions(const nlohmann::json& result, const std::string& file) {
  Placement placement;
  if (result.contains("positions")) {
    for (const auto& p : result["positions"])
      placement.push_back(PositionOf(p, file + ": positions"));
  } else if (result.contains("uavs") && result["uavs"].is_array()) {
    for (const auto& u : result["uavs"])
      placement.push_back(PositionOf(u.value("position", nlohmann::json()), file + ": uavs"));
  } else if (result.contains("position")) {
    placement.push_back(PositionOf(result["position"], file + ": position"));
  } else {
    throw ConfigError("--result", file +
                                      ": no \"position\" or \"positions\": not the JSON of "
                                      "rlpos-sim position, train or eval");
  }
  return placement;
}

map::MapPlacement PlacementFromResult(const Scenario& s, const std::string& file) {
  nlohmann::json result;
  try {
    result = ReadJsonFile(file);
  } catch (const ConfigError& e) {
    throw ConfigError("--result", file + ": " + e.problem());
  }
  if (!result.is_object())
    throw ConfigError("--result", file + ": not a JSON object");
  const std::string scenario = result.value("scenario", s.name);
  if (scenario != s.name)
    throw ConfigError("--result",
                      file + " is a result of scenario " + scenario + ", not " + s.name);
  const Placement placement = ResultPositions(result, file);
  if (placement.size() != s.uavs.size())
    throw ConfigError("--result", file + " has " + std::to_string(placement.size()) +
                                      " position(s); scenario " + s.name + " has " +
                                      std::to_string(s.uavs.size()) + " UAV(s)");
  for (const Vec3& p : placement)
    CheckUavPosition(s, p, "--result");
  // position prints its positioner; train (its algorithm) and eval do not.
  std::string label = result.value("positioner", std::string());
  if (label.empty())
    label = result.contains("algorithm") ? "rl" : "placement";
  return {label + " (" + file.substr(file.find_last_of('/') + 1) + ")", placement};
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find(separator, start)) != std::string::npos; start = end + 1)
    parts.push_back(text.substr(start, end - start));
  parts.push_back(text.substr(start));
  return parts;
}

// LABEL=x,y,z[;x,y,z]: a positioner's placement, one x,y,z per UAV.
map::MapPlacement NamedPlacement(const Scenario& s, const std::string& text) {
  const std::size_t eq = text.find('=');
  const std::string label = text.substr(0, eq);
  if (eq == std::string::npos || label.empty() || label.size() > kMaxLabelLength)
    throw ConfigError("--placement", "expected LABEL=x,y,z[;x,y,z] (a label of 1 to " +
                                         std::to_string(kMaxLabelLength) + " characters), got \"" +
                                         text + "\"");
  for (const unsigned char c : label) {
    if (c < 0x20 || c >= 0x7f)
      throw ConfigError("--placement", "the label \"" + label +
                                           "\" has a character that is not "
                                           "printable ASCII");
  }
  return {label, ParsePlacement(s, Split(text.substr(eq + 1), ';'), "--placement " + label)};
}

std::vector<map::MapPlacement> Placements(const Scenario& s, const RenderCommand& r) {
  if (!r.positions.empty())
    return {{"given placement", ParsePlacement(s, r.positions, "--position")}};
  if (!r.result.empty())
    return {PlacementFromResult(s, r.result)};
  if (!r.placements.empty()) {
    std::vector<map::MapPlacement> out;
    for (const std::string& text : r.placements)
      out.push_back(NamedPlacement(s, text));
    return out;
  }
  return {{"baseline", s.InitialPlacement()}};
}

// The walked paths of the moving UEs, at the scenario's RngRun, up to its horizon.
void AddUePaths(map::MapScene& scene) {
  const Scenario& s = scene.scenario;
  if (!AnyUeMoves(s))
    return;
  const double horizon = TrajectoryHorizon(s);
  for (const UeTrajectory& trajectory : UeTrajectories(s, horizon)) {
    std::vector<Vec3> path;
    for (const Waypoint& w : trajectory.waypoints()) {
      const bool same = !path.empty() && path.back().x == w.position.x &&
                        path.back().y == w.position.y && path.back().z == w.position.z;
      if (!same)
        path.push_back(w.position);
    }
    scene.ue_paths.push_back(std::move(path));
  }
  scene.ue_paths_label = "UE paths, 0-" + FormatNumber(horizon) + " s (RngRun " +
                         std::to_string(s.simulation.run) + ")";
}

}  // namespace

void AddRender(CLI::App& app, RenderCommand& r, CommonOptions& options) {
  r.command = app.add_subcommand("render", "Render a map of the scenario (PNG or SVG)");
  r.command->add_option("scenario", options.scenario_file, kScenarioHelp)->required();
  auto* position =
      r.command
          ->add_option("--position", r.positions,
                       "UAV position x,y,z (m); once per UAV (default: the scenario's baseline)")
          ->expected(1)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  auto* result = r.command->add_option(
      "--result", r.result,
      "Take the placement from the JSON of rlpos-sim position, train or eval");
  auto* placement =
      r.command
          ->add_option("--placement", r.placements,
                       "LABEL=x,y,z[;x,y,z]: a positioner's placement; repeat to compare several")
          ->expected(1)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  position->excludes(result)->excludes(placement);
  result->excludes(placement);
  r.command->add_option("--trajectory", r.trajectory,
                        "Show the rl flight of this trajectory.csv (rlpos-sim train)");
  r.command->add_flag("--side", r.side, "Add the elevation views (x-z and y-z)");
  r.command->add_option("--out", r.out, "The map: FILE.png or FILE.svg")->required();
}

int RunRender(const CommonOptions& options, const RenderCommand& r) {
  const map::MapFormat format = map::MapFormatOf(r.out, "--out");
  map::MapScene scene;
  scene.scenario = LoadScenarioFor(options, {});
  scene.placements = Placements(scene.scenario, r);
  scene.side_views = r.side;
  if (!r.trajectory.empty()) {
    const map::Flight flight = map::ReadTrajectoryCsv(r.trajectory, scene.scenario, "--trajectory");
    scene.flight = flight.paths;
    scene.flight_label = "rl flight (evaluation episode " + std::to_string(flight.episode) + ")";
  }
  AddUePaths(scene);
  map::AddLinks(scene);
  WriteFileAtomically(r.out, map::RenderMap(scene, format));
  std::cout << r.out << std::endl;
  return kExitOk;
}

}  // namespace rlpos::sim
