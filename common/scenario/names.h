#pragma once
// The names users, campaigns and the wire spell, declared once: command-line checks and help,
// campaign and scenario validation, the worker's order checks and the wire's enum tables take
// their lists from here.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rlpos {

// env.fidelity and a campaign's train.fidelity: the model alone, or full ns-3.
inline constexpr std::array<std::string_view, 2> kFidelities{"analytic", "packet"};

// agent.algorithm, in the order reports list them.
inline constexpr std::array<std::string_view, 3> kAlgorithms{"dqn", "ppo", "sac"};

// Every positioner, in the order reports list them: offsets are the paper's positions 1-5 around
// rl's, rl a trained policy's greedy flight.
inline constexpr std::array<std::string_view, 5> kPositioners{"baseline", "offsets", "centroid",
                                                              "oracle", "rl"};

// The positioners that place UAVs with no trained policy: a campaign's position jobs.
inline constexpr std::array<std::string_view, 3> kPlacingPositioners{"baseline", "centroid",
                                                                     "oracle"};

// The positioners that decide again at every env.decision_interval as the UEs move (rlpos-sim
// track). Every other positioner is held: decided once for t = 0.
inline constexpr std::array<std::string_view, 2> kTrackingPositioners{"oracle-track",
                                                                      "centroid-track"};

// env.reward.name: the rewards worker/env/gym/reward.cc makes, in the order of its factories.
inline constexpr std::array<std::string_view, 2> kRewards{"paper", "demand_aware"};

// `a` then `b`.
template <std::size_t A, std::size_t B>
constexpr std::array<std::string_view, A + B> Concat(const std::array<std::string_view, A>& a,
                                                     const std::array<std::string_view, B>& b) {
  std::array<std::string_view, A + B> out{};
  for (std::size_t i = 0; i < A; ++i)
    out[i] = a[i];
  for (std::size_t i = 0; i < B; ++i)
    out[A + i] = b[i];
  return out;
}

// env.observations: the scenario's own fields (their count follows its UAVs and UEs), and the
// fields that mean the same in every scenario (worker/env/gym/general_observation.h).
inline constexpr std::array<std::string_view, 7> kScenarioObservations{
    "x", "y", "z", "n_los", "throughput", "demands_met", "snr"};
inline constexpr std::array<std::string_view, 7> kGeneralObservations{
    "zone", "ues", "heights", "others", "coverage", "lookahead", "best"};

// What rlpos-sim track takes for --positioner (it refuses rl and offsets, saying why).
inline constexpr auto kTrackPositioners = Concat(kPositioners, kTrackingPositioners);

template <std::size_t N>
constexpr bool IsOneOf(std::string_view name, const std::array<std::string_view, N>& names) {
  for (std::string_view n : names) {
    if (n == name)
      return true;
  }
  return false;
}

inline constexpr auto kObservations = Concat(kScenarioObservations, kGeneralObservations);

template <std::size_t N>
std::vector<std::string> NameList(const std::array<std::string_view, N>& names) {
  return {names.begin(), names.end()};
}

// "a, b or c"
template <std::size_t N>
std::string Alternatives(const std::array<std::string_view, N>& names) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0)
      text += i + 1 == N ? " or " : ", ";
    text += names[i];
  }
  return text;
}

// "a|b|c", as a command line's help shows choices.
template <std::size_t N>
std::string Choices(const std::array<std::string_view, N>& names) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i)
    text += (i > 0 ? "|" : "") + std::string(names[i]);
  return text;
}

}  // namespace rlpos
