#pragma once
// Observations that mean the same in every scenario, for a policy that places UAVs in venues it
// never saw (the generalist): what surrounds the UAV whose turn it is, relative to it, in slots
// of fixed count, instead of the scenario's own coordinates and UE count. env.observations names
// them beside the per-scenario fields (moves.h):
//   "zone"    3 values: the UAV's position within its zone, each in [0, 1];
//   "ues"     env.observed_ues slots of kUeSlotWidth, the nearest UEs first (horizontal
//             distance, then index), then empty slots of zeros:
//             [present, dx, dy, dz, los, snr, mine] with the offsets from the UAV in units of
//             kObservedRangeM (clipped to +-kObservedOffsetLimit), los of the UE's link to its
//             serving UAV, the SNR scaled from [kObservedSnrLowDb, kObservedSnrHighDb] to [0, 1],
//             and mine = 1 if the UAV serves the UE;
//   "heights" env.height_map x env.height_map cells of env.step metres centred below the UAV,
//             row by row (y, then x): the top of the tallest building over each cell in units
//             of kObservedRangeM (0 where there is none), clipped to kObservedHeightLimit;
//   "others"  kOtherUavSlots slots of [present, dx, dy, dz], the other UAVs nearest first.
// Two more are the model observations (the analytic model's, at any fidelity), which the env
// computes into the step's info (StepInfo::coverage, ::lookahead):
//   "coverage"  a coarse map of the UAV's zone, env.coverage_map cells per side, row by row
//               (y, then x): for each cell, the best reward over the altitudes of the move
//               lattice at the lattice column nearest the cell's centre (the other UAVs where
//               they are), in units of the reward's bound (CoverageRewardBound); then each
//               cell's best altitude within the zone, in [0, 1]. 0 and 0 where the column lies
//               inside a building at every altitude; last, the offset from the UAV to the best
//               cell's column at its best altitude (dx, dy, dz in moves of env.step, clipped to
//               +-kPointerStepLimit);
//   "lookahead" for each of env.actions, the model's reward at the move's destination minus its
//               reward here, times kLookaheadGain over the reward's bound, clipped to [-1, 1] (0
//               for a move that goes nowhere).
// And one of the episode's course, which the env keeps in StepInfo::below_best:
//   "best"      the episode's best reward so far minus the reward here, times kLookaheadGain
//               over the reward's bound, clipped to [0, 1]: 0 at the best of the flight, the
//               step a placement keeps (greedy_flight.h). With agent.improvement_reward it tells
//               the critic how far the next improvement is.
// A scenario with more UEs than slots shows the nearest; the slots and the cells hold no
// scenario's size, so their layout is the same in every scenario of the same env settings.
#include <cstddef>
#include <string_view>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {

constexpr double kObservedRangeM = 100.0;
constexpr double kObservedOffsetLimit = 4.0;
constexpr double kObservedHeightLimit = 4.0;
constexpr int kUeSlotWidth = 7;
constexpr int kOtherUavSlots = 5;
constexpr int kOtherUavSlotWidth = 4;
// "coverage"'s pointer to the map's best, in moves (env.step), clipped: one move is a quarter of
// its range, so that the last moves to the best stand out after scaling to [-1, 1].
constexpr double kPointerStepLimit = 4.0;
// "lookahead"'s reward changes, in tenths of the reward's bound (clipped to [-1, 1]): one UE of
// ten coming into LoS is 0.8, not 0.08.
constexpr double kLookaheadGain = 10.0;

// True for "zone", "ues", "heights", "others", "coverage", "lookahead" and "best".
bool IsGeneralObservation(std::string_view field);
// Whether the field needs the env to evaluate positions other than the UAVs' own.
bool IsModelObservation(std::string_view field);
// The most the scenario's reward can be (the sum of its weights), at least 1e-9.
double CoverageRewardBound(const Scenario& scenario);

// The UAVs other than `uav`, by horizontal distance from it (ties: lower index): the order of
// "others".
std::vector<std::size_t> OtherUavsNearestFirst(const StepInfo& info, std::size_t uav);

// Appends the field's bounds to `box` / its values for the UAV info.active_uav to `out`.
void AddGeneralBounds(const Scenario& scenario, std::string_view field, BoxSpace& box);
void AddGeneralObservation(const Scenario& scenario, const StepInfo& info, std::string_view field,
                           std::vector<double>& out);

}  // namespace rlpos
