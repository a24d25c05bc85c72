// PPO's policy flown without libtorch (PpoGreedyPolicy): it reads what PpoAgent saved and picks
// what PpoAgent picks greedily, for the MLP and the set network, masks included; a file of
// another network, a damaged one or none is refused in one line that names it.
#include "worker/learning/agent_base/ppo_greedy_policy.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "tests/worker/learning/agent/plain_training.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/agent_base/ppo_actor_head.h"
#include "worker/learning/agent_base/ppo_objective.h"

namespace rlpos::ppo_greedy_policy_test {
namespace {

// 3 values, then 4 UE slots of 7; 7 actions.
constexpr SlotBlock kSlots{3, 4, 7};
constexpr int kDim = 3 + 4 * 7;
constexpr int kActions = 7;

AgentSpec Spec(std::uint64_t seed, std::vector<int> hidden, std::vector<int> encoder = {}) {
  AgentSpec spec = PlainTrainingSpec("ppo", seed, 1);
  spec.hidden = std::move(hidden);
  spec.ue_encoder = std::move(encoder);
  return spec;
}

std::string Folder(const std::string& name) {
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("rlpos_ppo_greedy_" + name)).string();
  std::filesystem::remove_all(dir);
  return dir;
}

// Observations of values in [-1, 1], each UE slot present or empty; masks that forbid some moves.
struct Probe {
  std::vector<float> observation;
  ActionMask mask;
};

std::vector<Probe> Probes(int count) {
  std::mt19937 g(9);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::vector<Probe> probes;
  for (int i = 0; i < count; ++i) {
    Probe p;
    p.observation.resize(kDim);
    for (float& v : p.observation)
      v = value(g);
    for (int k = 0; k < kSlots.count; ++k) {
      float* slot = p.observation.data() + kSlots.offset + k * kSlots.width;
      if (g() % 3 == 0)
        std::fill(slot, slot + kSlots.width, -1.0f);
      else
        slot[0] = 1.0f;
    }
    if (i % 2 == 1) {
      p.mask.assign(kActions, 1);
      for (int a = 0; a < kActions; ++a)
        p.mask[static_cast<std::size_t>(a)] = g() % 3 != 0;
      p.mask[static_cast<std::size_t>(i % kActions)] = 1;  // at least one allowed
    }
    probes.push_back(std::move(p));
  }
  return probes;
}

// A PpoAgent after a little exploring (so its weights are no longer only the seeded ones), saved.
std::string SavedAgent(const AgentSpec& spec, const std::string& name) {
  PpoAgent agent(spec, kDim, kActions, 0, kSlots);
  const std::vector<Probe> probes = Probes(64);
  for (std::size_t i = 0; i + 1 < probes.size(); ++i) {
    const int action = agent.Act(probes[i].observation, {}, true);
    agent.Observe({probes[i].observation,
                   action,
                   static_cast<float>(action % 3),
                   probes[i + 1].observation,
                   false,
                   {},
                   {},
                   i % 8 == 7});
  }
  const std::string dir = Folder(name);
  agent.Save(dir);
  return dir;
}

void ExpectSameChoices(const AgentSpec& spec, const std::string& name) {
  const std::string dir = SavedAgent(spec, name);
  PpoAgent agent(spec, kDim, kActions, 0, kSlots);
  agent.Load(dir);
  PpoGreedyPolicy greedy(spec, kDim, kActions, kSlots);
  greedy.Load(dir);
  int masked = 0, differing_from_first = 0;
  const std::vector<Probe> probes = Probes(600);
  const int first = agent.Act(probes[0].observation, probes[0].mask, false);
  for (const Probe& p : probes) {
    const int want = agent.Act(p.observation, p.mask, false);
    EXPECT_EQ(greedy.Act(p.observation, p.mask, false), want);
    masked += !p.mask.empty() && !p.mask[static_cast<std::size_t>(want)] ? 1 : 0;
    differing_from_first += want != first ? 1 : 0;
  }
  EXPECT_EQ(masked, 0);
  EXPECT_GT(differing_from_first, 50) << "the probes should not all pick one action";
  std::filesystem::remove_all(dir);
}

TEST(PpoGreedyPolicy, PicksWhatPpoAgentPicksWithAnMlp) {
  ExpectSameChoices(Spec(3, {32, 32}), "mlp");
}

TEST(PpoGreedyPolicy, PicksWhatPpoAgentPicksWithTheUeSet) {
  ExpectSameChoices(Spec(5, {16}, {8, 8}), "set");
}

// A forbidden action far ahead would leave the allowed ones' probabilities all 0 (a tie that picks
// the lowest index) unless the mask lowers its logit first.
TEST(PpoActorHead, PicksTheBestAllowedActionWhenAForbiddenOneDominates) {
  std::vector<float> logits{200.0f, 0.0f, 0.5f};
  const ActionMask mask{0, 1, 1};
  MaskLogits(mask, 3, logits.data());
  EXPECT_EQ(logits[0], 200.0f + kForbiddenLogit);
  std::vector<float> p(3);
  Softmax(logits.data(), 3, p.data());
  EXPECT_EQ(MostProbableAllowed(p.data(), mask, 3), 2);
  // A mask that allows nothing counts as none.
  std::vector<float> unmasked{1.0f, 2.0f};
  MaskLogits(ActionMask{0, 0}, 2, unmasked.data());
  EXPECT_EQ(unmasked, (std::vector<float>{1.0f, 2.0f}));
}

TEST(PpoGreedyPolicy, RefusesAMaskThatAllowsNothingAndExploring) {
  PpoGreedyPolicy greedy(Spec(3, {8}), kDim, kActions, kSlots);
  const std::vector<float> x(kDim, 0.0f);
  EXPECT_THROW(greedy.Act(x, ActionMask(kActions, 0), false), std::invalid_argument);
  EXPECT_THROW(greedy.Act(x, {}, true), std::logic_error);
  EXPECT_THROW(greedy.Save(Folder("nowhere")), std::logic_error);
}

std::string LoadError(const AgentSpec& spec, const std::string& dir) {
  PpoGreedyPolicy greedy(spec, kDim, kActions, kSlots);
  try {
    greedy.Load(dir);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(PpoGreedyPolicy, RefusesAPolicyFileOfAnotherNetworkOrDamagedOrMissing) {
  const std::string mlp = SavedAgent(Spec(3, {32, 32}), "refuse_mlp");
  const std::string set = SavedAgent(Spec(5, {16}, {8, 8}), "refuse_set");
  const std::string file = mlp + "/policy.pt";
  EXPECT_NE(LoadError(Spec(3, {32, 16}), mlp).find(file + ": the policy's network shape differs"),
            std::string::npos);
  EXPECT_NE(LoadError(Spec(3, {32}), mlp).find(file + ": the policy's network shape differs"),
            std::string::npos);
  EXPECT_NE(LoadError(Spec(3, {32, 32}, {8}), mlp).find(file + ": the policy's network has no UE"),
            std::string::npos);
  EXPECT_NE(LoadError(Spec(5, {16}), set).find(set + "/policy.pt: the policy's network has a UE"),
            std::string::npos);
  EXPECT_NE(LoadError(Spec(5, {16}, {8}), set).find("the policy's network shape differs"),
            std::string::npos);
  // Cut short: not a policy file.
  std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
  EXPECT_EQ(LoadError(Spec(3, {32, 32}), mlp), file + ": not a policy file of this network");
  std::filesystem::remove(file);
  EXPECT_EQ(LoadError(Spec(3, {32, 32}), mlp), file + ": no such policy file");
  std::filesystem::remove_all(mlp);
  std::filesystem::remove_all(set);
}

}  // namespace
}  // namespace rlpos::ppo_greedy_policy_test
