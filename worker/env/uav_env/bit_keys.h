#pragma once
// Keys of the env's memos, compared bit for bit: a double as the bits it is, and the mix that
// spreads such bits over a hash's low bits (lattice coordinates differ in their high bits only).
#include <cstdint>
#include <cstring>

namespace rlpos {

inline std::uint64_t DoubleBits(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

// splitmix64's finaliser.
inline std::uint64_t MixBits(std::uint64_t z) {
  z ^= z >> 30;
  z *= 0xbf58476d1ce4e5b9ULL;
  z ^= z >> 27;
  z *= 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace rlpos
