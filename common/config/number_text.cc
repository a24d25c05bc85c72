#include "config/number_text.h"

#include <charconv>
#include <system_error>

namespace rlpos {

std::string FormatNumber(double x) {
  // Shortest text that reads back as x: "50", "44.5", "0.1" (not "50.000000" nor "5e+01").
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return error == std::errc() ? std::string(buffer, end) : std::to_string(x);
}

std::string FormatPosition(const Vec3& p) {
  return FormatNumber(p.x) + "," + FormatNumber(p.y) + "," + FormatNumber(p.z);
}

}  // namespace rlpos
