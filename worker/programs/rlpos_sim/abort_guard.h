#pragma once
namespace rlpos {
// ns-3 reports fatal errors by printing a message and calling std::terminate/abort. This turns
// that into a clean one-line failure on stderr and exit code `exit_code`, with nothing on stdout.
void InstallAbortGuard(const char* program, int exit_code);
}  // namespace rlpos
