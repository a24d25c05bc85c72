#pragma once
// What every classic env's Reset owes its seed (cartpole_env_test.cc, pendulum_env_test.cc).
#include <gtest/gtest.h>

#include <cstdint>

namespace rlpos {

// Reset with `seed`, `a` and `b` start alike; `a` reset with seed + 1 starts otherwise. The
// start of `seed`, for the caller's checks of its range.
template <typename Env>
auto ExpectResetFollowsTheSeed(Env& a, Env& b, std::uint64_t seed) {
  const auto first = a.Reset(seed);
  EXPECT_EQ(first, b.Reset(seed));
  EXPECT_NE(first, a.Reset(seed + 1));
  return first;
}

}  // namespace rlpos
