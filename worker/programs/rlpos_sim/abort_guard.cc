#include "worker/programs/rlpos_sim/abort_guard.h"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace rlpos {
namespace {
char g_message[256];
std::size_t g_message_length = 0;
int g_exit_code = 3;

extern "C" void OnAbort(int) {
  // Only async-signal-safe calls here.
  const ssize_t ignored = write(STDERR_FILENO, g_message, g_message_length);
  (void)ignored;
  _exit(g_exit_code);
}
}  // namespace

void InstallAbortGuard(const char* program, int exit_code) {
  g_exit_code = exit_code;
  const char* text = ": error: ns-3 aborted the simulation (its message is above)\n";
  std::strncpy(g_message, program, 64);
  std::strncat(g_message, text, sizeof(g_message) - std::strlen(g_message) - 1);
  g_message_length = std::strlen(g_message);
  std::signal(SIGABRT, OnAbort);
}

}  // namespace rlpos
