#pragma once
// The UAVs' discrete moves and the observation vector, from the scenario's env section.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {

// The functions that move a UAV take the scenario's buildings as `buildings`, the index
// BuildingObstacles(scenario.buildings) built once per env: a move's cost stays flat in the
// number of buildings (BuildingContaining scans them all).

// The placement after UAV `uav` takes `action` (an index into scenario.env.actions): one step in
// its direction, clamped to the UAV's zone. A move that would end inside a building, or closer
// than kMinUavSeparation to another UAV, leaves the UAV where it is. (With env.action_mask the
// agent never picks a move that leaves it where it is.)
Placement ApplyMove(const Scenario& scenario, const Obstacles& buildings, std::size_t uav,
                    int action, const Placement& from);
// The displacement of move `action` (an index into scenario.env.actions): env.step metres along
// its axis; "stay" is (0, 0, 0), and so is "to_best", whose displacement depends on the state
// (StepTowards).
Vec3 MoveDisplacement(const Scenario& scenario, int action);
// The index of "to_best" in scenario.env.actions, or -1.
int ToBestAction(const Scenario& scenario);
// "to_best": one move of UAV `uav` towards `target` (the coverage map's pointer): along the axis
// of the largest remaining offset (x, y, z on a tie) by env.step metres, or by the offset if that
// is less, so that the UAV lands on the target; if that move leaves the UAV where it is (a
// building, a zone edge, another UAV), the next largest axis's; (0, 0, 0) at the target or when
// no axis moves it.
Vec3 StepTowards(const Scenario& scenario, const Obstacles& buildings, std::size_t uav,
                 const Vec3& target, const Placement& from);
// Where UAV `uav` at `at` ends after `displacement` if no other UAV mattered: clamped to its
// zone, or `at` if that point is inside a building.
Vec3 TargetAlone(const Scenario& scenario, const Obstacles& buildings, std::size_t uav,
                 const Vec3& displacement, const Vec3& at);
// Where ApplyDisplacement puts UAV `uav`, without building the placement (an action mask asks
// this of every action at every step, its actions turned into displacements once).
Vec3 DisplacementTarget(const Scenario& scenario, const Obstacles& buildings, std::size_t uav,
                        const Vec3& displacement, const Placement& from);
// The placement after a displacement of UAV `uav` (env.action_space "continuous"), with the
// same rules.
Placement ApplyDisplacement(const Scenario& scenario, const Obstacles& buildings, std::size_t uav,
                            const Vec3& displacement, const Placement& from);
// A start for an exploring-starts episode, drawn from `seed`: each UAV in turn at a point of its
// zone on the lattice of env.step moves through its initial position (so a discrete policy
// trained from there meets the cells it flies through from the baseline), not inside a
// building nor too close to an earlier UAV. A UAV that finds no such point in 64 draws keeps its
// initial position.
Placement RandomStart(const Scenario& scenario, const Obstacles& buildings, std::uint64_t seed);
// The continuous action space: a displacement in metres, each component in [-step, step].
BoxSpace DisplacementBounds(const Scenario& scenario);

// The bounds an observed SNR is clipped to (dB), in the observation and the state.
constexpr double kObservedSnrLowDb = -20.0;
constexpr double kObservedSnrHighDb = 60.0;

// Observation layout and bounds from scenario.env.observations ("snr" expands to one per UE;
// "x", "y" and "z" to one per UAV; "n_los", "throughput" and "demands_met" are one value each;
// the general fields "zone", "ues", "heights", "others", "coverage", "lookahead" and "best" as
// general_observation.h says). With several UAVs a one-hot of the UAV whose turn it is follows
// (a shared policy moves them in turn), unless every field is one of the general ones, which
// already see the world from that UAV.
BoxSpace ObservationBounds(const Scenario& scenario);
// Where the "ues" field's slots lie in that layout; nothing without the field.
std::optional<SlotBlock> UeSlotBlock(const Scenario& scenario);
std::vector<double> MakeObservation(const Scenario& scenario, const StepInfo& info);

}  // namespace rlpos
