#include "common/scenario/mobility_settings.h"

#include <tuple>

namespace rlpos {
namespace {

using nlohmann::json;

constexpr const char* kPath = "/ues/<i>/mobility";

// [min, max] m/s, min above 0; min = max: one speed.
void ReadSpeeds(RandomWaypointSpec& w, const json& v, const std::string& path) {
  std::tie(w.speed_min, w.speed_max) = ReadInterval(v, path, true);
  CheckedNumber(v[0], JoinPath(path, 0), Positive());
}

json SpeedsJson(const RandomWaypointSpec& w) {
  return {w.speed_min, w.speed_max};
}

void ReadTarget(CrowdSpec& c, const json& v, const std::string& path) {
  c.target = ReadGroundPoint(v, path);
}

json TargetJson(const CrowdSpec& c) {
  return {c.target.x, c.target.y};
}

}  // namespace

const std::vector<std::string>& MobilityModelNames() {
  // In the order of MobilityModel.
  static const std::vector<std::string> names{"static", "random_walk", "random_waypoint",
                                              "gauss_markov", "crowd"};
  return names;
}

std::string MobilityModelName(MobilityModel model) {
  return MobilityModelNames()[static_cast<std::size_t>(model)];
}

std::optional<MobilityModel> ParseMobilityModel(const std::string& name) {
  const auto& names = MobilityModelNames();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name)
      return static_cast<MobilityModel>(i);
  }
  return std::nullopt;
}

const SettingsTable<RandomWalkSpec>& RandomWalkSettings() {
  static const SettingsTable<RandomWalkSpec> table{
      "mobility.random_walk",
      kPath,
      "\"model\": \"random_walk\": legs of `change_interval` s at `speed`, each in a direction "
      "drawn anew.",
      {{"speed", &RandomWalkSpec::speed, Positive(), "walking speed", "m/s"},
       {"change_interval", &RandomWalkSpec::change_interval, Positive(), "length of a leg", "s"}}};
  return table;
}

const SettingsTable<RandomWaypointSpec>& RandomWaypointSettings() {
  static const SettingsTable<RandomWaypointSpec> table{
      "mobility.random_waypoint",
      kPath,
      "\"model\": \"random_waypoint\": to a spot drawn uniformly on the walkable ground, at a "
      "speed uniform in `speed`, then a pause; again.",
      {{"speed", CustomValue<RandomWaypointSpec>{ReadSpeeds, SpeedsJson, "[min, max]"}, NoRange(),
        "the interval the speed of each walk is drawn from (min above 0)", "m/s"},
       {"pause", &RandomWaypointSpec::pause, NonNegative(), "pause at each waypoint", "s"}}};
  return table;
}

const SettingsTable<GaussMarkovSpec>& GaussMarkovSettings() {
  static const SettingsTable<GaussMarkovSpec> table{
      "mobility.gauss_markov",
      kPath,
      "\"model\": \"gauss_markov\": every `step` s, speed and direction are `alpha` x their last "
      "value + (1 - `alpha`) x their mean + sqrt(1 - `alpha`^2) x Gaussian noise (Camp, Boleng "
      "and Davies 2002). The noise's standard deviation is 0.3 x `speed` for the speed and pi/4 "
      "rad for the direction; the speed is kept in [0, 2 x `speed`]; the mean direction is drawn "
      "once per UE.",
      {{"speed", &GaussMarkovSpec::speed, Positive(), "the mean speed", "m/s"},
       {"alpha", &GaussMarkovSpec::alpha, Between(0.0, 1.0),
        "memory: 0 draws speed and direction afresh each step, 1 keeps them"},
       {"step", &GaussMarkovSpec::step, Positive(), "time between updates", "s"}}};
  return table;
}

const SettingsTable<CrowdSpec>& CrowdSettings() {
  static const SettingsTable<CrowdSpec> table{
      "mobility.crowd",
      kPath,
      "\"model\": \"crowd\": waits until `start`, walks to a spot drawn in the disc of `radius` "
      "around `target` (round the buildings), stays `dwell` s, then walks to a spot drawn in the "
      "whole venue and stays there. UEs with the same crowd settings are one group.",
      {{"target",
        CustomValue<CrowdSpec>{ReadTarget, TargetJson, "[x, y]"},
        NoRange(),
        "where the crowd gathers",
        "m",
        {},
        "[x, y]: where the crowd gathers"},
       {"radius", &CrowdSpec::radius, NonNegative(), "radius of the gathering", "m"},
       {"speed", &CrowdSpec::speed, Positive(), "walking speed", "m/s"},
       {"start", &CrowdSpec::start, NonNegative(), "when the UE sets off", "s"},
       {"dwell", &CrowdSpec::dwell, NonNegative(), "time spent at the gathering", "s"}}};
  return table;
}

MobilitySpec ReadMobility(const json& v, const std::string& path) {
  ObjectReader r(v, path);
  MobilitySpec m;
  m.model = *ParseMobilityModel(r.String("model", "static", MobilityModelNames()));
  switch (m.model) {
    case MobilityModel::kStatic: {
      // Documents written before the other models carry random_walk's keys: read, unused.
      RandomWalkSpec unused;
      ReadSettings(r, RandomWalkSettings(), unused);
      break;
    }
    case MobilityModel::kRandomWalk:
      ReadSettings(r, RandomWalkSettings(), m.random_walk);
      break;
    case MobilityModel::kRandomWaypoint:
      ReadSettings(r, RandomWaypointSettings(), m.random_waypoint);
      break;
    case MobilityModel::kGaussMarkov:
      ReadSettings(r, GaussMarkovSettings(), m.gauss_markov);
      break;
    case MobilityModel::kCrowd:
      ReadSettings(r, CrowdSettings(), m.crowd);
      break;
  }
  r.Finish();
  return m;
}

// The model and its own parameters only.
json MobilityJson(const MobilitySpec& m) {
  json out = json::object();
  switch (m.model) {
    case MobilityModel::kStatic:
      break;
    case MobilityModel::kRandomWalk:
      out = SettingsJson(m.random_walk, RandomWalkSettings());
      break;
    case MobilityModel::kRandomWaypoint:
      out = SettingsJson(m.random_waypoint, RandomWaypointSettings());
      break;
    case MobilityModel::kGaussMarkov:
      out = SettingsJson(m.gauss_markov, GaussMarkovSettings());
      break;
    case MobilityModel::kCrowd:
      out = SettingsJson(m.crowd, CrowdSettings());
      break;
  }
  out["model"] = MobilityModelName(m.model);
  return out;
}

}  // namespace rlpos
