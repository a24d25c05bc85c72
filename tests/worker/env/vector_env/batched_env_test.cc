// The batched env on scenario B: each of its envs follows exactly the trajectory of a single env
// with the same seeds and actions (next-step autoreset included), on any number of threads.
#include "worker/env/vector_env/batched_env.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/shared_placement_memo.h"
#include "worker/env/uav_env/uav_positioning_env.h"

namespace rlpos {
namespace {

const std::vector<std::string> kShort = {"env.fidelity=analytic", "env.episode_duration=1"};
const std::vector<std::string> kContinuous = {"agent.algorithm=sac", "env.action_space=continuous"};

Scenario LoadB(std::vector<std::string> overrides) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json", overrides);
}

// B without its buildings: the same spaces, other rewards.
Scenario OpenB(std::vector<std::string> overrides) {
  Scenario s = LoadB(overrides);
  s.name = "B-open";
  s.buildings.clear();
  return s;
}

// The buffers of one batch, and the BatchBuffers that point into them.
struct Batch {
  explicit Batch(const BatchedEnv& env)
      : n(env.NumEnvs()),
        d(env.ObservationDim()),
        a(env.ActionCount()),
        observations(n * d),
        rewards(n),
        terminated(n),
        truncated(n),
        n_los(n),
        throughput(n),
        demands(n),
        positions(n * env.UavCount() * 3),
        active(n),
        mask(n * a) {}
  BatchBuffers Buffers() {
    BatchBuffers b;
    b.observations = observations.data();
    b.rewards = rewards.data();
    b.terminated = reinterpret_cast<bool*>(terminated.data());
    b.truncated = reinterpret_cast<bool*>(truncated.data());
    b.n_los = n_los.data();
    b.throughput_mbps = throughput.data();
    b.demands_met = demands.data();
    b.positions = positions.data();
    b.active_uav = active.data();
    b.action_mask = mask.data();
    return b;
  }
  bool operator==(const Batch& o) const {
    return observations == o.observations && rewards == o.rewards && terminated == o.terminated &&
           truncated == o.truncated && n_los == o.n_los && throughput == o.throughput &&
           demands == o.demands && positions == o.positions && active == o.active && mask == o.mask;
  }
  std::size_t n, d, a;
  std::vector<float> observations;
  std::vector<double> rewards;
  std::vector<char> terminated, truncated;  // one byte each, as bool
  std::vector<std::int64_t> n_los;
  std::vector<double> throughput;
  std::vector<std::int64_t> demands;
  std::vector<double> positions;
  std::vector<std::int64_t> active;
  std::vector<std::int8_t> mask;
};
static_assert(sizeof(bool) == sizeof(char), "bool buffers are one byte per env");

// The single env's row as the batch writes it.
void ExpectRow(const Batch& b, std::size_t i, const UavPositioningEnv& env,
               const std::vector<double>& observation, const char* when) {
  for (std::size_t k = 0; k < b.d; ++k)
    EXPECT_EQ(b.observations[i * b.d + k], static_cast<float>(observation[k])) << when;
  const StepInfo& info = env.LastInfo();
  EXPECT_EQ(b.n_los[i], info.n_los) << when;
  EXPECT_EQ(b.throughput[i], info.throughput_mbps) << when;
  EXPECT_EQ(b.demands[i], info.demands_met) << when;
  EXPECT_EQ(b.positions[i * 3], info.positions[0].x) << when;
  EXPECT_EQ(b.positions[i * 3 + 1], info.positions[0].y) << when;
  EXPECT_EQ(b.positions[i * 3 + 2], info.positions[0].z) << when;
  const ActionMask mask = env.ValidActions();
  for (std::size_t a = 0; a < b.a; ++a)
    EXPECT_EQ(b.mask[i * b.a + a], mask.empty() ? 1 : mask[a]) << when;
}

// Random moves, the same for every run of a test.
std::vector<std::int64_t> Moves(std::mt19937& rng, std::size_t n, int actions) {
  std::uniform_int_distribution<std::int64_t> pick(0, actions - 1);
  std::vector<std::int64_t> moves(n);
  for (auto& m : moves)
    m = pick(rng);
  return moves;
}

TEST(BatchedEnv, EachEnvFollowsTheSingleEnvTrajectoryThroughAutoresets) {
  // Two scenarios alternate: env i gets scenarios[i % 2]. Episodes of 10 steps and of 6 steps.
  std::vector<std::string> six = kShort;
  six.push_back("env.episode_duration=0.6");
  const std::vector<Scenario> scenarios = {LoadB(kShort), OpenB(six)};
  const std::size_t n = 5;
  BatchedEnvOptions options;
  options.num_envs = n;
  options.threads = 2;
  BatchedEnv batched(scenarios, options);
  EXPECT_EQ(batched.ScenarioOf(3).name, "B-open");
  EXPECT_EQ(batched.ScenarioOf(4).name, "B");
  std::vector<std::unique_ptr<UavPositioningEnv>> singles;
  for (std::size_t i = 0; i < n; ++i)
    singles.push_back(std::make_unique<UavPositioningEnv>(scenarios[i % 2]));

  Batch b(batched);
  const std::vector<std::optional<std::uint64_t>> seeds = {11, 12, std::nullopt, 14, 15};
  batched.Reset(seeds, ResetOptions{true}, b.Buffers());  // exploring starts: seeds matter
  std::vector<bool> ended(n, false);
  std::vector<std::uint64_t> next_run(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t run = seeds[i] ? *seeds[i] : 1000000 + 1 + i;  // agent.seed 1
    ExpectRow(b, i, *singles[i], singles[i]->Reset(run, ResetOptions{true}), "reset");
    next_run[i] = run + 1;
  }
  std::mt19937 rng(7);
  int autoresets = 0;
  for (int t = 0; t < 25; ++t) {
    const auto moves = Moves(rng, n, 7);
    batched.Step(moves.data(), moves.size(), b.Buffers());
    for (std::size_t i = 0; i < n; ++i) {
      const std::string when = "step " + std::to_string(t) + ", env " + std::to_string(i);
      if (ended[i]) {  // the reference: Gymnasium's next-step autoreset, by hand
        ExpectRow(b, i, *singles[i], singles[i]->Reset(next_run[i]++), when.c_str());
        EXPECT_EQ(b.rewards[i], 0.0) << when;
        EXPECT_FALSE(b.terminated[i] || b.truncated[i]) << when;
        ended[i] = false;
        ++autoresets;
        continue;
      }
      const StepResult r = singles[i]->Step(static_cast<int>(moves[i]));
      ExpectRow(b, i, *singles[i], r.observation, when.c_str());
      EXPECT_EQ(b.rewards[i], r.reward) << when;
      EXPECT_EQ(static_cast<bool>(b.terminated[i]), r.terminated) << when;
      EXPECT_EQ(static_cast<bool>(b.truncated[i]), r.truncated) << when;
      ended[i] = r.terminated || r.truncated;
    }
  }
  EXPECT_GE(autoresets, 2 * static_cast<int>(n));
  // A reset without seeds takes each env's next run.
  batched.Reset({}, ResetOptions{true}, b.Buffers());
  for (std::size_t i = 0; i < n; ++i)
    ExpectRow(b, i, *singles[i], singles[i]->Reset(next_run[i], ResetOptions{true}), "reset");
}

TEST(BatchedEnv, AnEndedEnvIgnoresItsActionAndReturnsTheResetObservation) {
  const Scenario s = LoadB(kShort);
  BatchedEnvOptions options;
  options.num_envs = 2;
  BatchedEnv batched({s}, options);
  Batch b(batched);
  batched.Reset({}, ResetOptions{}, b.Buffers());
  const std::int64_t backward = 3, up = 0;
  ASSERT_EQ(s.env.actions[backward], "backward");
  ASSERT_EQ(s.env.actions[up], "up");
  std::vector<std::int64_t> moves = {backward, backward};
  for (int t = 1; t <= 10; ++t) {
    batched.Step(moves.data(), 2, b.Buffers());
    EXPECT_EQ(b.truncated[0] != 0, t == 10);
    EXPECT_FALSE(b.terminated[0]);
  }
  EXPECT_EQ(b.positions[1], 30.0);  // y: the building south of the baseline stopped it
  EXPECT_GT(b.rewards[0], 0.0);
  moves = {up, up};  // ignored: both envs reset
  batched.Step(moves.data(), 2, b.Buffers());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(
        std::vector<float>(b.observations.begin() + 4 * i, b.observations.begin() + 4 * i + 4),
        (std::vector<float>{50, 50, 25, 1}));  // the baseline, not one step up
    EXPECT_EQ(b.rewards[i], 0.0);
    EXPECT_FALSE(b.terminated[i] || b.truncated[i]);
  }
  batched.Step(moves.data(), 2, b.Buffers());  // the next episode takes the action
  EXPECT_EQ(b.observations[2], 30.0f);         // z: 25 + 5
  EXPECT_FALSE(b.truncated[0]);
}

// The same seeds and actions on 1 and on 4 threads give the same bytes.
Batch RunBatch(const std::vector<Scenario>& scenarios, std::size_t n, std::size_t threads,
               bool continuous) {
  BatchedEnvOptions options;
  options.num_envs = n;
  options.threads = threads;
  options.seed = 3;
  BatchedEnv batched(scenarios, options);
  EXPECT_EQ(batched.Threads(), threads);
  Batch b(batched);
  batched.Reset({}, ResetOptions{true}, b.Buffers());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> component(-5, 5);
  for (int t = 0; t < 23; ++t) {
    if (continuous) {
      std::vector<double> d(3 * n);
      for (auto& v : d)
        v = component(rng);
      batched.StepContinuous(d.data(), d.size(), b.Buffers());
    } else {
      const auto moves = Moves(rng, n, 7);
      batched.Step(moves.data(), moves.size(), b.Buffers());
    }
  }
  return b;
}

// A training resets each env with its own options (exploring starts for some episodes, the
// baseline for others) and reads the observations as the env gives them, unclipped doubles.
TEST(BatchedEnv, ResetsEachEnvWithItsOwnOptionsAndGivesRawObservations) {
  const Scenario b = LoadB(kShort);
  BatchedEnvOptions options;
  options.num_envs = 3;
  options.threads = 2;
  BatchedEnv batched({b}, options);
  std::vector<ResetOptions> resets(3);
  resets[0].random_start = true;
  resets[2].random_start = true;
  Batch batch(batched);
  BatchBuffers buffers = batch.Buffers();
  std::vector<double> raw(3 * batched.ObservationDim());
  buffers.raw_observations = raw.data();
  batched.Reset({11u, 12u, 13u}, resets, buffers);
  for (std::size_t i = 0; i < 3; ++i) {
    UavPositioningEnv single(b);
    const std::vector<double> expected = single.Reset(11 + i, resets[i]);
    ExpectRow(batch, i, single, expected, "reset with its own options");
    EXPECT_EQ(
        std::vector<double>(raw.begin() + static_cast<long>(i * batched.ObservationDim()),
                            raw.begin() + static_cast<long>((i + 1) * batched.ObservationDim())),
        expected);
    EXPECT_EQ(batched.LastInfo(i).positions[0].x, single.LastInfo().positions[0].x);
    EXPECT_EQ(batched.LastInfo(i).positions[0].y, single.LastInfo().positions[0].y);
  }
  // The baseline start and a random one differ, or the options did not reach the envs.
  EXPECT_NE(batch.positions[0 * 3] + batch.positions[0 * 3 + 1] + batch.positions[0 * 3 + 2],
            batch.positions[1 * 3] + batch.positions[1 * 3 + 1] + batch.positions[1 * 3 + 2]);
  EXPECT_THROW(batched.Reset({}, std::vector<ResetOptions>(2), buffers), std::invalid_argument);
}

TEST(BatchedEnv, OneThreadOrFourGiveTheSameResults) {
  const std::vector<Scenario> scenarios = {LoadB(kShort), OpenB(kShort)};
  EXPECT_TRUE(RunBatch(scenarios, 13, 1, false) == RunBatch(scenarios, 13, 4, false));
  std::vector<std::string> continuous = kShort;
  continuous.insert(continuous.end(), kContinuous.begin(), kContinuous.end());
  EXPECT_TRUE(RunBatch({LoadB(continuous)}, 13, 1, true) ==
              RunBatch({LoadB(continuous)}, 13, 4, true));
}

TEST(BatchedEnv, EnvsOfOneScenarioShareOneBoundedMemo) {
  // B, open B and B again (the same content): envs 0, 2, 3, 5 share one memo, 1 and 4 another.
  BatchedEnv env({LoadB(kShort), OpenB(kShort), LoadB(kShort)}, BatchedEnvOptions{6, 1, 2});
  for (std::size_t i : {2, 3, 5})
    EXPECT_EQ(&env.MemoOf(i), &env.MemoOf(0)) << i;
  EXPECT_EQ(&env.MemoOf(4), &env.MemoOf(1));
  EXPECT_NE(&env.MemoOf(1), &env.MemoOf(0));
  // Sized for its four envs (four single envs' budgets), within the few MiB of a scenario.
  EXPECT_EQ(env.MemoOf(0).Capacity(),
            SharedPlacementMemo(1, 4, SharedPlacementMemo::BudgetFor(4)).Capacity());
  Batch batch(env);
  env.Reset({}, ResetOptions{}, batch.Buffers());
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::int64_t> move(
      0, static_cast<std::int64_t>(env.ActionCount()) - 1);
  std::vector<std::int64_t> actions(env.NumEnvs());
  for (int k = 0; k < 50; ++k) {
    for (auto& a : actions)
      a = move(rng);
    env.Step(actions.data(), actions.size(), batch.Buffers());
  }
  // Every env of B started at B's start: one entry, not four, for the placements they share.
  EXPECT_GT(env.MemoOf(0).Size(), 0u);
  EXPECT_LT(env.MemoOf(0).Size(), 4u * 50u);
  EXPECT_LE(env.MemoOf(0).Size(), env.MemoOf(0).Capacity());
}

TEST(BatchedEnv, ContinuousEnvsFollowTheSingleEnv) {
  std::vector<std::string> overrides = kShort;
  overrides.insert(overrides.end(), kContinuous.begin(), kContinuous.end());
  const Scenario s = LoadB(overrides);
  BatchedEnvOptions options;
  options.num_envs = 3;
  BatchedEnv batched({s}, options);
  EXPECT_EQ(batched.ActionCount(), 0u);
  EXPECT_FALSE(batched.HasActionMask());
  Batch b(batched);
  batched.Reset({1, 2, 3}, ResetOptions{true}, b.Buffers());
  std::vector<std::unique_ptr<UavPositioningEnv>> singles;
  for (std::size_t i = 0; i < 3; ++i) {
    singles.push_back(std::make_unique<UavPositioningEnv>(s));
    singles[i]->Reset(i + 1, ResetOptions{true});
  }
  const std::vector<double> d = {0, -5, 0, 0.5, 2.5, -5, 5, 5, 5};
  batched.StepContinuous(d.data(), d.size(), b.Buffers());
  for (std::size_t i = 0; i < 3; ++i) {
    const StepResult r = singles[i]->StepContinuous({d[3 * i], d[3 * i + 1], d[3 * i + 2]});
    ExpectRow(b, i, *singles[i], r.observation, "continuous");
    EXPECT_EQ(b.rewards[i], r.reward);
  }
}

TEST(BatchedEnv, RefusesScenariosWhoseSpacesDiffer) {
  BatchedEnvOptions options;
  options.num_envs = 4;
  const Scenario b = LoadB(kShort);
  std::vector<std::string> fewer = kShort;
  fewer.push_back("env.observations=[\"x\",\"y\",\"z\"]");
  try {
    BatchedEnv batched({b, OpenB(kShort), OpenB(fewer)}, options);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "scenario 2 (B-open) and scenario 0 (B) differ in their observation space (3 "
                 "against 4 values, or other bounds): a batch needs one");
  }
  std::vector<std::string> continuous = kShort;
  continuous.insert(continuous.end(), kContinuous.begin(), kContinuous.end());
  EXPECT_THROW(BatchedEnv({b, LoadB(continuous)}, options), std::invalid_argument);
  // A scenario that no env gets does not count: 1 env of a list of 2.
  options.num_envs = 1;
  EXPECT_NO_THROW(BatchedEnv({b, LoadB(continuous)}, options));
}

TEST(BatchedEnv, RefusesPacketFidelityAndBadSizes) {
  BatchedEnvOptions options;
  try {
    BatchedEnv batched({LoadB({"env.fidelity=packet"})}, options);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("one process per packet-level env"), std::string::npos)
        << e.what();
  }
  for (std::size_t n : {std::size_t{0}, kMaxBatchedEnvs + 1}) {
    options.num_envs = n;
    EXPECT_THROW(BatchedEnv({LoadB(kShort)}, options), std::invalid_argument) << n;
  }
  options.num_envs = 2;
  EXPECT_THROW(BatchedEnv({}, options), std::invalid_argument);
  BatchedEnv batched({LoadB(kShort)}, options);
  Batch b(batched);
  EXPECT_THROW(batched.Reset({1, 2, 3}, ResetOptions{}, b.Buffers()), std::invalid_argument);
}

TEST(BatchedEnv, RefusesBadActionsBeforeSteppingAnyEnv) {
  BatchedEnvOptions options;
  options.num_envs = 3;
  BatchedEnv batched({LoadB(kShort)}, options);
  Batch b(batched);
  const std::vector<std::int64_t> fine = {0, 1, 2};
  EXPECT_THROW(batched.Step(fine.data(), 3, b.Buffers()), std::logic_error);  // not reset yet
  batched.Reset({}, ResetOptions{}, b.Buffers());
  const Batch before = b;
  try {
    const std::vector<std::int64_t> bad = {0, 7, 2};
    batched.Step(bad.data(), 3, b.Buffers());
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "actions[1]: expected a move index in [0, 7), got 7");
  }
  const std::vector<std::int64_t> negative = {-1, 0, 0};
  EXPECT_THROW(batched.Step(negative.data(), 3, b.Buffers()), std::invalid_argument);
  EXPECT_THROW(batched.Step(fine.data(), 2, b.Buffers()), std::invalid_argument);  // shape
  const std::vector<double> d(9, 0.0);
  EXPECT_THROW(batched.StepContinuous(d.data(), 9, b.Buffers()), std::invalid_argument);
  EXPECT_TRUE(b == before);  // nothing written
  // No env moved: the next step is the first of the episode for all three.
  batched.Step(fine.data(), 3, b.Buffers());
  BatchedEnv fresh({LoadB(kShort)}, options);
  Batch expected(fresh);
  fresh.Reset({}, ResetOptions{}, expected.Buffers());
  fresh.Step(fine.data(), 3, expected.Buffers());
  EXPECT_TRUE(b == expected);

  std::vector<std::string> continuous = kShort;
  continuous.insert(continuous.end(), kContinuous.begin(), kContinuous.end());
  BatchedEnv boxes({LoadB(continuous)}, options);
  Batch c(boxes);
  boxes.Reset({}, ResetOptions{}, c.Buffers());
  std::vector<double> far = {0, 0, 0, 0, 5.5, 0, 0, 0, 0};
  try {
    boxes.StepContinuous(far.data(), far.size(), c.Buffers());
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "actions[1][1]: expected within [-5, 5] m, got 5.5");
  }
  far[4] = std::nan("");
  EXPECT_THROW(boxes.StepContinuous(far.data(), far.size(), c.Buffers()), std::invalid_argument);
  EXPECT_THROW(boxes.StepContinuous(far.data(), 6, c.Buffers()), std::invalid_argument);
  EXPECT_THROW(boxes.Step(fine.data(), 3, c.Buffers()), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
