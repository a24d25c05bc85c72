#pragma once
// Whether a scenario document contradicts the scenario a policy was trained on. A policy is
// bound to the MDP it learned: a document may restate the trained scenario's fields, not change
// them. What it leaves unstated is the trained scenario's (a policy trained with env.step 10 is
// placed in plain B with env.step 10). Fields that do not shape the MDP stay the document's own:
// name and description, log_level, the simulation section (an evaluation's duration and runs),
// env.fidelity (a policy trained analytic is evaluated at packet level) and the agent section
// (the policy brings its own algorithm and hyperparameters). The UAVs are compared whether stated
// or not: they are what is placed.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

struct Contradiction {
  std::string path;     // JSON path of the first field that differs, e.g. "/env/step"
  std::string problem;  // e.g. "5 in the scenario, 10 in the policy"
};

// `stated`: a scenario document as written (file and --set overrides, no defaults filled in).
// Its fields overlay `trained`; the first field (venue, buildings, UEs, UAVs, env, Wi-Fi,
// traffic, propagation, in that order) where the result differs from `trained` is returned.
std::optional<Contradiction> FirstContradiction(const Scenario& trained,
                                                const nlohmann::json& stated);

}  // namespace rlpos
