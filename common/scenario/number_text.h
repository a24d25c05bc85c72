#pragma once
// Numbers as text that reads back exactly: what goes into messages, overrides and command lines.
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

// Shortest text that reads back as the same double ("2", "0.5", "44.5").
std::string FormatNumber(double x);
// "x,y,z" as rlpos-sim --position takes it.
std::string FormatPosition(const Vec3& p);
// For people: "(80.0, 90.0, 12.0) (80.0, 10.0, 12.0)", one decimal, a triple per UAV.
std::string DescribePlacement(const Placement& placement);
// For people: a duration as "1h02m", "3m20s", "42s".
std::string FormatDuration(double seconds);

}  // namespace rlpos
