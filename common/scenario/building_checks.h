#pragma once
// The buildings' own checks, part of CheckScenarioGeometry: each shape a valid polygon, each
// building inside the venue, no two sharing a volume.
#include "common/scenario/scenario.h"

namespace rlpos {

// Adjacent city buildings share walls, and their imported corners agree only to rounding: an
// overlap thinner than this (m) everywhere is taken for a shared wall. Two box buildings keep
// the exact rule they always had (any shared volume is an overlap).
constexpr double kBuildingOverlapTolerance = 1e-3;

// Throws ConfigError naming the JSON path: a footprint's ring that is not simple
// (/buildings/<i>/footprint, /buildings/<i>/holes/<k>: RingDefect's words), a hole outside the
// outer ring or over another, a building outside the venue, two buildings that overlap (the
// later one's path). The first building at fault, in that order, is reported.
void CheckBuildings(const Scenario& scenario);

// Buildings `a` and `b` share a volume: their height ranges and their ground shapes' interiors
// overlap (deeper than kBuildingOverlapTolerance unless both are boxes).
bool BuildingsOverlap(const BuildingSpec& a, const BuildingSpec& b);

}  // namespace rlpos
