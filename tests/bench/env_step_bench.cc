// Steps per second of the env in both fidelities, with the DQN agent acting and learning, and
// the share of a packet-level step spent outside ns-3 (agent + monitors + env bookkeeping).
//   rlpos-bench-env SCENARIO.json [ANALYTIC_STEPS] [PACKET_STEPS]
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "common/config/config_error.h"
#include "tests/support/program_usage.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent/dqn_agent.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Figures {
  double steps_per_s = 0;
  double outside_ns3_share = 0;
};

Figures Run(rlpos::Scenario s, const std::string& fidelity, int steps) {
  s.env.fidelity = fidelity;
  s.env.episode_duration = steps * s.env.decision_interval;
  rlpos::UavPositioningEnv env(s);
  rlpos::DqnAgent agent(s.agent, static_cast<int>(env.ObservationSpace().Dim()),
                        env.ActionSpace().n);
  const auto space = env.ObservationSpace();
  auto obs = space.Normalise(env.Reset(s.agent.seed * 1000000 + 1));
  const double ns3_before = env.WallSecondsInNs3();  // the reset's warm-up is not a step
  const auto start = Clock::now();
  auto mask = env.ValidActions();
  for (int i = 0; i < steps; ++i) {
    const int action = agent.Act(obs, mask, true);
    const auto r = env.Step(action);
    auto next = space.Normalise(r.observation);
    auto next_mask = env.ValidActions();
    agent.Observe({obs,
                   action,
                   static_cast<float>(r.reward),
                   next,
                   r.terminated,
                   next_mask,
                   {},
                   r.terminated || r.truncated});
    obs = std::move(next);
    mask = std::move(next_mask);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  const double in_ns3 = env.WallSecondsInNs3() - ns3_before;
  return {steps / wall, fidelity == "packet" ? 1.0 - in_ns3 / wall : 1.0};
}

double AnalyticEnvAloneStepsPerSecond(rlpos::Scenario s, int steps) {
  s.env.fidelity = "analytic";
  rlpos::UavPositioningEnv env(s);
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> action(0, env.ActionSpace().n - 1);
  std::uint64_t episode = 1;
  env.Reset(episode);
  const auto start = Clock::now();
  for (int i = 0; i < steps; ++i) {
    const auto r = env.Step(action(rng));
    if (r.terminated || r.truncated)
      env.Reset(++episode);
  }
  return steps / std::chrono::duration<double>(Clock::now() - start).count();
}

// A step count argument: a whole number in [1, 10^9].
bool ParseSteps(const char* text, int& steps) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || errno != 0 || value < 1 || value > 1000000000)
    return false;
  steps = static_cast<int>(value);
  return true;
}

constexpr char kUsage[] =
    "usage: rlpos-bench-env SCENARIO.json [ANALYTIC_STEPS] [PACKET_STEPS] [ENV_ALONE_STEPS]\n";

}  // namespace

int main(int argc, char** argv) {
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc < 2 || argc > 5)
    return rlpos::testing::UsageError(kUsage);
  // The defaults: 2000 analytic steps, 50 packet-level ones, 200000 of the env alone.
  int steps[3] = {2000, 50, 200000};
  const char* const names[3] = {"ANALYTIC_STEPS", "PACKET_STEPS", "ENV_ALONE_STEPS"};
  for (int i = 2; i < argc; ++i) {
    if (!ParseSteps(argv[i], steps[i - 2])) {
      std::fprintf(stderr, "error: %s: expected a positive whole number of steps, got \"%s\"\n",
                   names[i - 2], argv[i]);
      return 1;
    }
  }
  rlpos::Scenario s;
  try {
    s = rlpos::LoadScenario(argv[1], {});
  } catch (const rlpos::ConfigError& e) {
    std::fprintf(stderr, "error: %s: %s\n", argv[1], e.describe().c_str());
    return 1;
  }
  try {
    const double alone = AnalyticEnvAloneStepsPerSecond(s, steps[2]);
    const Figures analytic = Run(s, "analytic", steps[0]);
    const Figures packet = Run(s, "packet", steps[1]);
    std::printf(
        "%-8s analytic %9.1f steps/s | packet %7.2f steps/s (%.0f ms simulated each), "
        "%.2f %% of a packet step outside ns-3 | analytic/packet %.0fx\n",
        s.name.c_str(), analytic.steps_per_s, packet.steps_per_s, s.env.decision_interval * 1e3,
        100.0 * packet.outside_ns3_share, analytic.steps_per_s / packet.steps_per_s);
    std::printf("%-8s analytic env alone (random actions, no agent) %9.0f steps/s\n",
                s.name.c_str(), alone);
  } catch (const std::exception& e) {  // e.g. a scenario the analytic fidelity refuses
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
