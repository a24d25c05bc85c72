#pragma once
// A UE's "mobility": its model and the model's own settings, each model's declared once
// (mobility_settings.cc) for the parser, ToJson and the docs.
#include <optional>
#include <string>
#include <vector>

#include "common/config/setting.h"
#include "common/scenario/geometry.h"

namespace rlpos {

// How a UE moves (docs/scenarios.md, "UE mobility"). The trajectory itself is computed from
// this, the scenario's geometry and the RngRun by common/mobility, the same at every fidelity.
enum class MobilityModel { kStatic, kRandomWalk, kRandomWaypoint, kGaussMarkov, kCrowd };

// A straight leg of `change_interval` s at `speed` in a direction drawn anew each leg.
struct RandomWalkSpec {
  double speed = 1.0;
  double change_interval = 2.0;
};

// Walk to a point drawn uniformly in the venue at a speed drawn from [speed_min, speed_max],
// pause, draw the next.
struct RandomWaypointSpec {
  double speed_min = 0.5;
  double speed_max = 1.5;
  double pause = 2.0;
};

// Gauss-Markov: every `step` s, speed and direction are alpha x their last value plus
// (1 - alpha) x their mean plus sqrt(1 - alpha^2) x Gaussian noise (alpha 0: a random walk of
// independent draws, 1: a straight line).
struct GaussMarkovSpec {
  double speed = 1.0;
  double alpha = 0.75;
  double step = 1.0;
};

// A crowd: from `start` s, walk at `speed` to a spot within `radius` of `target`, stay there
// `dwell` s, then walk away to a spot drawn in the venue. UEs given the same crowd settings are
// one group.
struct CrowdSpec {
  Vec3 target;  // z ignored: the UE keeps its height
  double radius = 10.0;
  double speed = 1.2;
  double start = 0.0;
  double dwell = 30.0;
};

struct MobilitySpec {
  MobilityModel model = MobilityModel::kStatic;
  RandomWalkSpec random_walk;
  RandomWaypointSpec random_waypoint;
  GaussMarkovSpec gauss_markov;
  CrowdSpec crowd;
};

// "static", "random_walk", "random_waypoint", "gauss_markov", "crowd".
std::string MobilityModelName(MobilityModel model);
const std::vector<std::string>& MobilityModelNames();
// The model of `name`, or nullopt.
std::optional<MobilityModel> ParseMobilityModel(const std::string& name);

// Each model's own settings, read from the UE's "mobility" object beside "model".
const SettingsTable<RandomWalkSpec>& RandomWalkSettings();
const SettingsTable<RandomWaypointSpec>& RandomWaypointSettings();
const SettingsTable<GaussMarkovSpec>& GaussMarkovSettings();
const SettingsTable<CrowdSpec>& CrowdSettings();

// A UE's "mobility" object: "model" and that model's own settings.
MobilitySpec ReadMobility(const nlohmann::json& v, const std::string& path);
nlohmann::json MobilityJson(const MobilitySpec& m);

}  // namespace rlpos
