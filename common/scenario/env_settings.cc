#include "common/scenario/env_settings.h"

#include <algorithm>

#include "common/scenario/names.h"

namespace rlpos {
namespace {

bool Has(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

void CheckEnv(const EnvSpec& e, const ObjectReader& r) {
  if (e.height_map % 2 == 0)
    throw ConfigError(r.PathOf("height_map"), "must be odd (the UAV is over the middle cell)");
  if (e.decision_interval > e.episode_duration)
    throw ConfigError(r.PathOf("decision_interval"), "must not exceed the episode duration");
  if (Has(e.actions, "to_best") && !Has(e.observations, "coverage")) {
    throw ConfigError(r.PathOf("actions"),
                      "\"to_best\" moves towards the coverage map's best: add \"coverage\" to "
                      "env.observations");
  }
}

// Keys added after documents existed: written when used or set, so that those documents keep
// their bytes and campaigns their ids.
bool GeneralOrNot(const EnvSpec& e, int EnvSpec::*member) {
  return UsesGeneralObservations(e) || e.*member != EnvSpec{}.*member;
}

}  // namespace

bool UsesGeneralObservations(const EnvSpec& env) {
  return std::any_of(env.observations.begin(), env.observations.end(),
                     [](const std::string& f) { return IsOneOf(f, kGeneralObservations); });
}

namespace {

// What the agent sees: the fields and the sizes of the general ones (env's table, in order).
std::vector<Setting<EnvSpec>> ObservationSettings() {
  return {
      {"observations", &EnvSpec::observations, NoRange(),
       "what the agent sees: the scenario's own fields (`x`, `y`, `z`, `n_los`; `throughput`, "
       "`demands_met`, `snr` one per UE) and the fields that mean the same in every scenario "
       "(`zone`, `ues`, `heights`, `others`, `coverage`, `lookahead`, `best`)",
       "", NameList(kObservations)},
      {"observed_ues",
       &EnvSpec::observed_ues,
       Integers(1, 64),
       "UE slots of the `ues` observation, nearest first",
       "",
       {},
       nullptr,
       [](const EnvSpec& e) { return GeneralOrNot(e, &EnvSpec::observed_ues); }},
      {"height_map",
       &EnvSpec::height_map,
       Integers(1, 33),
       "cells per side of the `heights` observation (odd), `env.step` metres each",
       "",
       {},
       nullptr,
       [](const EnvSpec& e) { return GeneralOrNot(e, &EnvSpec::height_map); }},
      {"coverage_map",
       &EnvSpec::coverage_map,
       Integers(1, 16),
       "cells per side of the `coverage` observation, over the UAV's zone",
       "",
       {},
       nullptr,
       [](const EnvSpec& e) { return GeneralOrNot(e, &EnvSpec::coverage_map); }},
      {"coverage_refine",
       &EnvSpec::coverage_refine,
       Integers(0, 8),
       "moves around the coverage map's best cell's column, in x and y at every altitude, whose "
       "best column `coverage`'s pointer leads to if it beats the cell's (0: none)",
       "",
       {},
       nullptr,
       [](const EnvSpec& e) { return e.coverage_refine != EnvSpec{}.coverage_refine; }}};
}

// When the agent decides and what a decision may do (env's table, in order, after the above).
std::vector<Setting<EnvSpec>> DecisionSettings() {
  return {
      {"decision_interval", &EnvSpec::decision_interval, Positive(),
       "simulated time between actions (and a tracking positioner's decisions); the paper's", "s"},
      {"episode_duration", &EnvSpec::episode_duration, Positive(),
       "simulated time per episode; the paper's", "s"},
      {"action_mask", &EnvSpec::action_mask, NoRange(),
       "moves that would leave the UAV where it is (into a wall of the zone or a building) are "
       "masked: the agent neither takes them nor bootstraps from them. `false`: only clamped, as "
       "in the paper"},
      {"action_space",
       &EnvSpec::action_space,
       NoRange(),
       "`discrete`: the moves of `env.actions`. `continuous`: a displacement (dx, dy, dz) in "
       "metres, each in [-`env.step`, `env.step`] (a Gymnasium Box), clamped to the zone like a "
       "move; SAC's space. The oracle then searches a 1 m grid",
       "",
       {"discrete", "continuous"}},
      {"turn_steps",
       &EnvSpec::turn_steps,
       Integers(1, 1000000),
       "several UAVs take turns: the steps each UAV moves before the next one's turn",
       "",
       {},
       nullptr,
       [](const EnvSpec& e) { return e.turn_steps != EnvSpec{}.turn_steps; }}};
}

}  // namespace

const SettingsTable<EnvSpec>& EnvSettings() {
  static const SettingsTable<EnvSpec> table = [] {
    SettingsTable<EnvSpec> t{
        "env",
        "/env",
        "The gym env: how the agent moves the UAVs, what it observes, when it decides.",
        {{"fidelity", &EnvSpec::fidelity, NoRange(),
          "`packet`: every step an ns-3 run; `analytic`: the same channel, without packets", "",
          NameList(kFidelities)},
         {"step", &EnvSpec::step, Positive(), "a move's length", "m"},
         {"actions",
          &EnvSpec::actions,
          NoRange(),
          "the discrete moves: +z, -z, +y, -y, -x, +x, none; clamped to the zone, and a move into "
          "a building leaves the UAV in place. Also `to_best` (needs the `coverage` observation): "
          "one move towards where `coverage`'s pointer leads, the first of a shortest way there "
          "round the buildings on the zone's lattice of `env.step` moves; masked off once there",
          "",
          {"up", "down", "forward", "backward", "left", "right", "stay", "to_best"}}},
        CheckEnv};
    for (auto* part : {ObservationSettings, DecisionSettings}) {
      for (auto& setting : part())
        t.entries.push_back(std::move(setting));
    }
    return t;
  }();
  return table;
}

const SettingsTable<RewardSpec>& RewardSettings() {
  static const SettingsTable<RewardSpec> table{
      "env.reward",
      "/env/reward",
      "The reward of a step: w1 x nLoS / N + w2 x throughput / total demand, + w3 x demands met "
      "/ N with demand_aware.",
      {{"name", &RewardSpec::name, NoRange(),
        "`paper`: w1 x nLoS / N + w2 x throughput / total demand; `demand_aware`: plus w3 x the "
        "UEs whose SNR meets their demand's MCS / N",
        "", NameList(kRewards)},
       {"w1", &RewardSpec::w1, NonNegative(), "weight of the UEs in LoS, nLoS / N"},
       {"w2", &RewardSpec::w2, NonNegative(), "weight of throughput / total demand"},
       {"w3",
        &RewardSpec::w3,
        NonNegative(),
        "weight of demands met / N; default 0.2 with demand_aware, else 0",
        "",
        {},
        nullptr,
        nullptr,
        [](RewardSpec& r) { r.w3 = r.name == "demand_aware" ? 0.2 : 0.0; }}}};
  return table;
}

}  // namespace rlpos
