#pragma once
// The wall clock as the store records times: seconds since the Unix epoch.

namespace rlpos {

double WallClockSeconds();

}  // namespace rlpos
