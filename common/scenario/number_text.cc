#include "common/scenario/number_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
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

std::string DescribePlacement(const Placement& placement) {
  std::string text;
  char buffer[96];
  for (const auto& p : placement) {
    std::snprintf(buffer, sizeof buffer, "%s(%.1f, %.1f, %.1f)", text.empty() ? "" : " ", p.x, p.y,
                  p.z);
    text += buffer;
  }
  return text;
}

std::string FormatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%lds", s);
  }
  return text;
}

}  // namespace rlpos
