#pragma once
// Minimal leveled logging to stderr (stdout is reserved for results).
#include <string>

namespace rlpos {

enum class LogLevel { kError = 0, kWarning = 1, kInfo = 2, kDebug = 3 };

// "error" | "warning" | "info" | "debug"; anything else throws std::invalid_argument.
LogLevel ParseLogLevel(const std::string& name);
void SetLogLevel(LogLevel level);
LogLevel CurrentLogLevel();
void Log(LogLevel level, const std::string& message);

}  // namespace rlpos
