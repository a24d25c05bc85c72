#include "common/logging/log.h"

#include <atomic>
#include <cstdio>
#include <stdexcept>

namespace rlpos {
namespace {
std::atomic<int> g_level{static_cast<int>(LogLevel::kWarning)};
const char* const kNames[] = {"error", "warning", "info", "debug"};
}  // namespace

LogLevel ParseLogLevel(const std::string& name) {
  for (int i = 0; i < 4; ++i) {
    if (name == kNames[i])
      return static_cast<LogLevel>(i);
  }
  throw std::invalid_argument("unknown log level \"" + name + "\"");
}

void SetLogLevel(LogLevel level) {
  g_level = static_cast<int>(level);
}
LogLevel CurrentLogLevel() {
  return static_cast<LogLevel>(g_level.load());
}

void Log(LogLevel level, const std::string& message) {
  if (static_cast<int>(level) > g_level)
    return;
  std::fprintf(stderr, "[%s] %s\n", kNames[static_cast<int>(level)], message.c_str());
}

}  // namespace rlpos
