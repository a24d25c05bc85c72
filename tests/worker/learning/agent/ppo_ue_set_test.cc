// PPO with agent.ue_encoder (its networks take the UE slots as a set) on a synthetic env of UE
// slots: seeded to the bit, saved and loaded, checkpointed, and refusing networks of the other
// kind with one line that names the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "tests/worker/learning/agent/plain_training.h"
#include "worker/learning/agent/ppo_agent.h"

namespace rlpos::ppo_ue_set_test {
namespace {

// 2 values, then 4 UE slots of 7; 3 actions.
constexpr SlotBlock kSlots{2, 4, 7};
constexpr int kDim = 2 + 4 * 7;
constexpr int kActions = 3;

AgentSpec SetSpec(std::uint64_t seed, std::vector<int> encoder = {8}) {
  AgentSpec spec = PlainTrainingSpec("ppo", seed, 1);
  spec.hidden = {16};
  spec.ue_encoder = std::move(encoder);
  spec.ppo.rollout_steps = 32;
  spec.ppo.learning_rate = 3e-3;
  return spec;
}

// A normalised observation: random values, each slot present (1) or empty (-1s).
std::vector<float> Observation(std::mt19937& g) {
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::vector<float> x(kDim);
  for (float& v : x)
    v = value(g);
  for (int k = 0; k < kSlots.count; ++k) {
    float* slot = x.data() + kSlots.offset + k * kSlots.width;
    if (g() % 2 == 0)
      slot[0] = 1.0f;
    else
      std::fill(slot, slot + kSlots.width, -1.0f);
  }
  return x;
}

int PresentSlots(const std::vector<float>& x) {
  int n = 0;
  for (int k = 0; k < kSlots.count; ++k)
    n += x[static_cast<std::size_t>(kSlots.offset + k * kSlots.width)] > 0.0f;
  return n;
}

// `steps` exploring steps, the same observations whatever the agent: the right action is the
// count of present UEs modulo 3.
void Drive(PpoAgent& agent, int steps, std::uint32_t observations_seed = 77) {
  std::mt19937 g(observations_seed);
  std::vector<float> observation = Observation(g);
  for (int i = 0; i < steps; ++i) {
    const int action = agent.Act(observation, {}, true);
    const float reward = action == PresentSlots(observation) % kActions ? 1.0f : 0.0f;
    std::vector<float> next = Observation(g);
    agent.Observe({observation, action, reward, next, false, {}, {}, i % 8 == 7});
    observation = std::move(next);
  }
}

std::vector<std::vector<float>> Probes() {
  std::mt19937 g(5);
  std::vector<std::vector<float>> probes;
  for (int i = 0; i < 6; ++i)
    probes.push_back(Observation(g));
  return probes;
}

std::vector<std::vector<float>> ProbabilitiesOf(const PpoAgent& agent) {
  std::vector<std::vector<float>> p;
  for (const auto& x : Probes())
    p.push_back(agent.Probabilities(x, {}));
  return p;
}

std::string Bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

// The error `load` throws: one line that starts with `file`.
template <typename Load>
std::string OneLineError(Load load, const std::string& file) {
  try {
    load();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file + ": ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "no error for " << file;
  return "";
}

TEST(PpoUeSet, NeedsTheUeSlots) {
  EXPECT_THROW(PpoAgent(SetSpec(1), kDim, kActions), std::invalid_argument);
}

TEST(PpoUeSet, SameSeedSameParametersToTheBitOtherSeedOther) {
  const auto train = [](std::uint64_t seed, const std::string& name) {
    PpoAgent agent(SetSpec(seed), kDim, kActions, 0, kSlots);
    Drive(agent, 96);  // three updates
    TempDir dir(name);
    agent.Save(dir.path.string());
    return std::vector<std::string>{Bytes(dir.path / "policy.pt"), Bytes(dir.path / "value.pt")};
  };
  // Compared whole, not printed: a failure would dump the archives' bytes.
  const auto a = train(11, "rlpos-ppo-ueset-a");
  ASSERT_FALSE(a[0].empty());
  EXPECT_TRUE(train(11, "rlpos-ppo-ueset-b") == a) << "the same seed saved other networks";
  EXPECT_TRUE(train(12, "rlpos-ppo-ueset-c") != a) << "another seed saved the same networks";
}

TEST(PpoUeSet, LearnsFromTheSet) {
  PpoAgent agent(SetSpec(3), kDim, kActions, 0, kSlots);
  const auto before = ProbabilitiesOf(agent);
  Drive(agent, 64);
  EXPECT_NE(ProbabilitiesOf(agent), before);
}

TEST(PpoUeSet, SaveLoadRoundTripAndTheOtherKindIsRefused) {
  PpoAgent trained(SetSpec(5), kDim, kActions, 0, kSlots);
  Drive(trained, 64);
  TempDir dir("rlpos-ppo-ueset-roundtrip");
  trained.Save(dir.path.string());
  PpoAgent loaded(SetSpec(99), kDim, kActions, 0, kSlots);
  EXPECT_NE(ProbabilitiesOf(loaded), ProbabilitiesOf(trained));
  loaded.Load(dir.path.string());
  EXPECT_EQ(ProbabilitiesOf(loaded), ProbabilitiesOf(trained));

  const std::string policy = (dir.path / "policy.pt").string();
  // Saved with the encoder, loaded into an agent without one.
  PpoAgent plain(SetSpec(5, {}), kDim, kActions, 0, kSlots);
  EXPECT_NE(OneLineError([&] { plain.Load(dir.path.string()); }, policy).find("agent.ue_encoder"),
            std::string::npos);
  // Another encoder: wider, or deeper.
  PpoAgent wider(SetSpec(5, {16}), kDim, kActions, 0, kSlots);
  EXPECT_NE(OneLineError([&] { wider.Load(dir.path.string()); }, policy).find("shape differs"),
            std::string::npos);
  PpoAgent deeper(SetSpec(5, {8, 8}), kDim, kActions, 0, kSlots);
  EXPECT_NE(OneLineError([&] { deeper.Load(dir.path.string()); }, policy).find("shape differs"),
            std::string::npos);

  // Saved without the encoder, loaded into an agent with one.
  TempDir plain_dir("rlpos-ppo-ueset-plain");
  plain.Save(plain_dir.path.string());
  const std::string plain_policy = (plain_dir.path / "policy.pt").string();
  EXPECT_NE(OneLineError([&] { loaded.Load(plain_dir.path.string()); }, plain_policy)
                .find("no UE encoder"),
            std::string::npos);
}

TEST(PpoUeSet, RestoresTheKeptPolicy) {
  PpoAgent agent(SetSpec(5), kDim, kActions, 0, kSlots);
  Drive(agent, 32);
  agent.KeepPolicy();
  const auto kept = ProbabilitiesOf(agent);
  Drive(agent, 64, 78);
  EXPECT_NE(ProbabilitiesOf(agent), kept);
  agent.RestoreKeptPolicy();
  EXPECT_EQ(ProbabilitiesOf(agent), kept);
}

TEST(PpoUeSet, ATrainingStateResumesExactlyAndOnlyIntoItsKind) {
  const std::string file =
      (std::filesystem::temp_directory_path() / "rlpos-ppo-ueset-state").string();
  PpoAgent a(SetSpec(5), kDim, kActions, 320, kSlots);
  Drive(a, 64);
  ASSERT_TRUE(a.AtRolloutStart());
  a.SaveTrainingState(file);
  PpoAgent b(SetSpec(99), kDim, kActions, 320, kSlots);
  b.LoadTrainingState(file);
  EXPECT_EQ(ProbabilitiesOf(b), ProbabilitiesOf(a));
  Drive(a, 96, 78);
  Drive(b, 96, 78);
  EXPECT_EQ(ProbabilitiesOf(b), ProbabilitiesOf(a));

  PpoAgent plain(SetSpec(5, {}), kDim, kActions, 320, kSlots);
  EXPECT_NE(OneLineError([&] { plain.LoadTrainingState(file); }, file).find("agent.ue_encoder"),
            std::string::npos);
  PpoAgent other_slots(SetSpec(5), kDim, kActions, 320, SlotBlock{0, 4, 7});
  OneLineError([&] { other_slots.LoadTrainingState(file); }, file);
  plain.SaveTrainingState(file);
  EXPECT_NE(OneLineError([&] { a.LoadTrainingState(file); }, file).find("agent.ue_encoder"),
            std::string::npos);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace rlpos::ppo_ue_set_test
