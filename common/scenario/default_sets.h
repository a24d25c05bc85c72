#pragma once
// Named default sets: the settings a kind of run starts from, before the scenario's own keys are
// read and the user's --set is applied. Declared once here, beside the settings tables; the
// commands that use them name them, and `rlpos-sim describe defaults` prints them.
#include <string>
#include <vector>

namespace rlpos {

struct DefaultSet {
  std::string name;                    // "ppo", "any-scenario", ...
  std::string summary;                 // one line: when it applies
  std::vector<std::string> overrides;  // --set texts ("key=value"), applied in order
};

// Every set, in the order `describe defaults` prints them.
const std::vector<DefaultSet>& DefaultSets();

// The set named `name`; throws std::invalid_argument naming the known ones when there is none.
const DefaultSet& DefaultSetNamed(const std::string& name);

// The set of `algorithm` ("dqn", "ppo", "sac"): the agent and the action space it flies.
const DefaultSet& AlgorithmDefaults(const std::string& algorithm);

// The policy for any scenario (rlpos-sim train --generated or --scenarios): "any-scenario" for
// one UAV, "any-scenario-several" when the training draws scenarios of several.
const DefaultSet& AnyScenarioDefaults(int max_uavs);

}  // namespace rlpos
