#pragma once
// Deterministic fuzz inputs: random bytes and mutations of valid texts, from a fixed seed, so
// that a failure reproduces with the same iteration number.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

namespace rlpos::testing {

class FuzzInput {
 public:
  explicit FuzzInput(std::uint64_t seed) : rng_(seed) {}

  std::size_t Below(std::size_t n) { return n == 0 ? 0 : rng_() % n; }
  bool Chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  std::string RandomBytes(std::size_t max_length);
  // 1 to 4 edits: byte flips, inserted and deleted ranges, duplicated ranges, truncation, and
  // tokens that parsers trip on ("NaN", "1e999", "\u0000", "..", deep brackets...).
  std::string Mutate(const std::string& text);
  // A number that breaks assumptions: NaN, infinities, 0, negatives, huge, denormal.
  double WeirdDouble();
  // `text` (valid JSON) with one value somewhere in its tree replaced by an odd one (negative,
  // huge, tiny, another type, null): input that parses, for the checks behind the parser.
  std::string MutateJsonValue(const std::string& text);
  std::int64_t WeirdInteger();

 private:
  std::mt19937_64 rng_;
};

}  // namespace rlpos::testing
