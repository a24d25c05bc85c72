#include "tests/fuzz/fuzz_input.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace rlpos::testing {

std::string FuzzInput::RandomBytes(std::size_t max_length) {
  std::string out(Below(max_length + 1), '\0');
  for (char& c : out)
    c = static_cast<char>(rng_() & 0xff);
  return out;
}

std::string FuzzInput::Mutate(const std::string& text) {
  static const std::vector<std::string> kTokens = {"NaN",
                                                   "-1",
                                                   "0",
                                                   "1e999",
                                                   "-1e999",
                                                   "18446744073709551616",
                                                   "null",
                                                   "true",
                                                   "\"",
                                                   "\\u0000",
                                                   "\\",
                                                   "..",
                                                   "../",
                                                   "/",
                                                   "[",
                                                   "]",
                                                   "{",
                                                   "}",
                                                   ",",
                                                   ":",
                                                   "\"\":",
                                                   "[[[[[[[[",
                                                   std::string(1, '\0'),
                                                   "\xff\xfe",
                                                   "\xc3",
                                                   "{\"a\":",
                                                   "1.7976931348623157e308",
                                                   "-0"};
  std::string out = text;
  const std::size_t edits = 1 + Below(4);
  for (std::size_t e = 0; e < edits; ++e) {
    const std::size_t at = Below(out.size() + 1);
    switch (Below(6)) {
      case 0:  // flip a byte
        if (!out.empty())
          out[Below(out.size())] = static_cast<char>(rng_() & 0xff);
        break;
      case 1:  // insert random bytes
        out.insert(at, RandomBytes(8));
        break;
      case 2:  // delete a range
        out.erase(at, Below(16) + 1);
        break;
      case 3:  // duplicate a range
        if (at < out.size())
          out.insert(Below(out.size() + 1), out.substr(at, Below(64) + 1));
        break;
      case 4:  // truncate
        out.resize(std::min(out.size(), at));
        break;
      default:  // insert a token
        out.insert(at, kTokens[Below(kTokens.size())]);
    }
  }
  return out;
}

std::string FuzzInput::MutateJsonValue(const std::string& text) {
  nlohmann::json document = nlohmann::json::parse(text);
  nlohmann::json* node = &document;
  while ((node->is_object() || node->is_array()) && !node->empty() && !Chance(0.15)) {
    auto it = node->begin();
    std::advance(it, static_cast<long>(Below(node->size())));
    node = &*it;
  }
  static const std::vector<nlohmann::json> kValues = {-1,
                                                      0,
                                                      1,
                                                      4,
                                                      5.5,
                                                      100,
                                                      1e308,
                                                      -1e308,
                                                      1e-320,
                                                      9223372036854775807LL,
                                                      18446744073709551615ULL,
                                                      -9223372036854775807LL,
                                                      "x",
                                                      "",
                                                      "../../etc",
                                                      nullptr,
                                                      true,
                                                      nlohmann::json::array(),
                                                      nlohmann::json::object(),
                                                      nlohmann::json::array({1, 2, 3})};
  *node = kValues[Below(kValues.size())];
  return document.dump();
}

double FuzzInput::WeirdDouble() {
  static const double kValues[] = {std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(),
                                   0.0,
                                   -0.0,
                                   -1.0,
                                   1e12,
                                   1e308,
                                   std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::lowest()};
  if (Chance(0.5))
    return kValues[Below(sizeof kValues / sizeof kValues[0])];
  return std::uniform_real_distribution<double>(-1e4, 1e4)(rng_);
}

std::int64_t FuzzInput::WeirdInteger() {
  static const std::int64_t kValues[] = {0,
                                         -1,
                                         1,
                                         std::numeric_limits<std::int32_t>::max(),
                                         std::numeric_limits<std::int32_t>::min(),
                                         std::numeric_limits<std::int64_t>::max(),
                                         std::numeric_limits<std::int64_t>::min()};
  if (Chance(0.5))
    return kValues[Below(sizeof kValues / sizeof kValues[0])];
  return static_cast<std::int64_t>(rng_());
}

}  // namespace rlpos::testing
