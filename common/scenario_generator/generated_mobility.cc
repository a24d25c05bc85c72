#include "common/scenario_generator/generated_mobility.h"

#include "common/config/config_error.h"
#include "common/mobility/mobility_text.h"
#include "common/mobility/ue_trajectories.h"
#include "common/mobility/walkable_area.h"
#include "common/scenario_generator/portable_random.h"

namespace rlpos {
namespace {

// Crowd targets drawn before the draw is given up.
constexpr int kTargetDraws = 100;

// Not the seed itself: the mobility stream must not repeat the layout's draws.
constexpr std::uint64_t kMobilityStream = 0x6d6f62696c697479ULL;

MobilitySpec Drawn(MobilityModel model, const Scenario& s, PortableRandom& random, bool& found) {
  MobilitySpec m;
  m.model = model;
  found = true;
  switch (model) {
    case MobilityModel::kRandomWaypoint:
      m.random_waypoint.pause = static_cast<double>(random.UniformInt(0, 4));
      break;
    case MobilityModel::kCrowd: {
      // A spot of open ground: its 2 m square off every building, so the crowd has room.
      const WalkableArea area(s);
      found = false;
      for (int draw = 0; draw < kTargetDraws && !found; ++draw) {
        const double x = random.UniformHalfMetres(2, s.venue.width - 2);
        const double y = random.UniformHalfMetres(2, s.venue.depth - 2);
        found = area.Contains(x, y) && area.Contains(x - 2, y - 2) && area.Contains(x + 2, y + 2) &&
                area.Contains(x - 2, y + 2) && area.Contains(x + 2, y - 2);
        m.crowd.target = {x, y, 0.0};
      }
      m.crowd.start = static_cast<double>(random.UniformInt(0, 20));
      m.crowd.dwell = static_cast<double>(random.UniformInt(30, 60));
      break;
    }
    case MobilityModel::kGaussMarkov:
    case MobilityModel::kRandomWalk:
    case MobilityModel::kStatic:
      break;  // the defaults: 1 m/s, alpha 0.75, step 1 s
  }
  return m;
}

}  // namespace

const std::vector<MobilityModel>& GeneratableMobilityModels() {
  static const std::vector<MobilityModel> models{
      MobilityModel::kRandomWaypoint, MobilityModel::kGaussMarkov, MobilityModel::kCrowd};
  return models;
}

MobilityModel ParseGeneratedMobility(const std::string& text, const std::string& what) {
  for (MobilityModel m : GeneratableMobilityModels()) {
    if (MobilityModelName(m) == text)
      return m;
  }
  throw ConfigError(what,
                    "unknown mobility \"" + text + "\" (random_waypoint, gauss_markov or crowd)");
}

bool DrawMobility(Scenario& scenario, MobilityModel model, std::uint64_t seed,
                  std::string& summary) {
  PortableRandom random(seed ^ kMobilityStream);
  bool found = false;
  const MobilitySpec m = Drawn(model, scenario, random, found);
  if (!found)
    return false;
  for (auto& ue : scenario.ues)
    ue.mobility = m;
  try {
    UeTrajectories(scenario);
  } catch (const ConfigError&) {
    return false;
  }
  summary = "UEs move: " + DescribeMobility(m);
  return true;
}

}  // namespace rlpos
