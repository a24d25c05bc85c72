#pragma once
// Checks every agent's policy passes alike (DQN, PPO, SAC): kept and restored, saved and loaded.
// `act(agent)` is what the policy does at one observation (Q values, action probabilities, a
// greedy continuous action), compared whole.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "common/scenario/scenario.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos {

// Two agents of the same seed (`spec_for(seed)`, trained on a fresh Env) act alike, two of other
// seeds otherwise.
template <typename Agent, typename Env, typename SpecFor, typename Act>
void ExpectTheSeedDecidesThePolicy(SpecFor spec_for, int observations, int actions, Act act) {
  const auto policy_of = [&](std::uint64_t seed) {
    Env env;
    const AgentSpec spec = spec_for(seed);
    Agent agent(spec, observations, actions);
    Train(env, agent, spec, 1);
    return act(agent);
  };
  EXPECT_EQ(policy_of(11), policy_of(11));
  EXPECT_NE(policy_of(11), policy_of(12));
}

// Nothing to restore before KeepPolicy; after it, learning on (a training by `learn_on`, seed 100)
// changes what the agent does, and RestoreKeptPolicy brings the kept policy back.
template <typename Env, typename Agent, typename Act>
void ExpectRestoresTheKeptPolicy(Env& env, Agent& agent, const AgentSpec& spec,
                                 const AgentSpec& learn_on, Act act) {
  EXPECT_THROW(agent.RestoreKeptPolicy(), std::logic_error);
  Train(env, agent, spec, 1);
  agent.KeepPolicy();
  const auto kept = act(agent);
  Train(env, agent, learn_on, 100);
  EXPECT_NE(act(agent), kept);
  agent.RestoreKeptPolicy();
  EXPECT_EQ(act(agent), kept);
}

// `trained` saved into the temporary folder `name`: `loaded` (of another seed, so it acts
// otherwise) acts as `trained` once it loads it, and an agent of another shape
// (`make_other_shape()`) refuses it. The folder is left for the caller's own checks; the caller
// removes it.
template <typename Agent, typename Act, typename MakeOtherShape>
std::filesystem::path ExpectSaveLoadRoundTrip(Agent& trained, Agent& loaded,
                                              const std::string& name, Act act,
                                              MakeOtherShape make_other_shape) {
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  trained.Save(dir.string());
  EXPECT_NE(act(loaded), act(trained));
  loaded.Load(dir.string());
  EXPECT_EQ(act(loaded), act(trained));
  auto other_shape = make_other_shape();
  EXPECT_THROW(other_shape.Load(dir.string()), std::runtime_error);
  return dir;
}

}  // namespace rlpos
