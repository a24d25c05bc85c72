#pragma once
// SIGTERM and SIGINT ask a daemon to stop cleanly: the handler only sets a flag that the main
// loop checks, so that readers, writers and child processes are shut down in order.
namespace rlpos {

void InstallStopSignalHandlers();
bool StopRequested();

}  // namespace rlpos
