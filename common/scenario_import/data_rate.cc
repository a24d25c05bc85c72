#include "common/scenario_import/data_rate.h"

#include <array>
#include <cstdlib>
#include <utility>

#include "common/config/config_error.h"

namespace rlpos {
namespace {

// ns-3's DataRate units and their bits per second (ns-3's own table: k and K are both 1000).
const std::array<std::pair<const char*, double>, 26>& Units() {
  static const std::array<std::pair<const char*, double>, 26> units = {{
      {"bps", 1.0},           {"b/s", 1.0},           {"Bps", 8.0},        {"B/s", 8.0},
      {"kbps", 1e3},          {"kb/s", 1e3},          {"Kbps", 1e3},       {"Kb/s", 1e3},
      {"kBps", 8e3},          {"kB/s", 8e3},          {"KBps", 8e3},       {"KB/s", 8e3},
      {"Kib/s", 1024.0},      {"KiB/s", 8192.0},      {"Mbps", 1e6},       {"Mb/s", 1e6},
      {"MBps", 8e6},          {"MB/s", 8e6},          {"Mib/s", 1048576.}, {"MiB/s", 8388608.},
      {"Gbps", 1e9},          {"Gb/s", 1e9},          {"GBps", 8e9},       {"GB/s", 8e9},
      {"Gib/s", 1073741824.}, {"GiB/s", 8589934592.},
  }};
  return units;
}

}  // namespace

double DataRateMbps(const std::string& text, const std::string& path) {
  const std::string quoted = "\"" + text + "\"";
  if (!text.empty() && text[0] == '-')
    throw ConfigError(path, "negative data rate " + quoted);
  const auto end = text.find_first_not_of("0123456789.");
  const std::string number = text.substr(0, end);
  const std::string unit = end == std::string::npos ? "" : text.substr(end);
  char* parsed_end = nullptr;
  const double value = number.empty() ? 0.0 : std::strtod(number.c_str(), &parsed_end);
  if (number.empty() || parsed_end != number.c_str() + number.size()) {
    throw ConfigError(path, "expected a data rate such as \"58.5Mbps\", got " + quoted);
  }
  double bits_per_unit = unit.empty() ? 1.0 : 0.0;
  for (const auto& [name, factor] : Units()) {
    if (unit == name)
      bits_per_unit = factor;
  }
  if (bits_per_unit == 0.0) {
    throw ConfigError(path,
                      "unknown data rate unit \"" + unit + "\" in " + quoted +
                          " (ns-3's units: bps, kbps, Mbps, Gbps, b/s, Mb/s, MBps, Mib/s, ...)");
  }
  if (value <= 0.0)
    throw ConfigError(path, "the data rate must be positive, got " + quoted);
  return value * bits_per_unit / 1e6;
}

}  // namespace rlpos
