#pragma once
// The UEs' mobility of a generated scenario (rlpos-sim generate --mobility): every UE moves by
// the one model, with parameters of pedestrians drawn from a stream of their own, so that the
// rest of the scenario is the same bytes as without --mobility.
#include <cstdint>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

// The models --mobility accepts: random_waypoint, gauss_markov, crowd.
const std::vector<MobilityModel>& GeneratableMobilityModels();
// "crowd" -> kCrowd; anything else is a ConfigError naming `what` and the models.
MobilityModel ParseGeneratedMobility(const std::string& text, const std::string& what);

// Gives every UE of `scenario` the model `model`, drawn from `seed`: random_waypoint at
// [0.5, 1.5] m/s with a pause of 0-4 s; gauss_markov at 1 m/s, alpha 0.75, step 1 s; crowd, one
// group gathering within 10 m of a spot drawn on the open ground at 1.2 m/s, from 0-20 s, for
// 30-60 s. Returns a phrase for the description; false if no draw let every UE walk for the
// scenario's horizon at RngRun 1 (then the caller draws again).
bool DrawMobility(Scenario& scenario, MobilityModel model, std::uint64_t seed,
                  std::string& summary);

}  // namespace rlpos
