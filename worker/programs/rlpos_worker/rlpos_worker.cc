// rlpos-worker: a headless worker of the campaign runner. It announces itself on DDS, runs the
// jobs the coordinator gives it in child rlpos-sim processes, and reports their results.
//   rlpos-worker [--slots N] [--id ID] [--work-dir DIR] [--domain N]
//                [--loopback TAG | --dds-config XML_OR_FILE] [--log-level L]
// Exit codes: 0 stopped by SIGTERM/SIGINT, 1 runtime failure (DDS), 2 bad input.
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <thread>

#include "common/process/executable_path.h"
#include "common/process/host_name.h"
#include "common/process/stop_signal.h"
#include "idl/dds/daemon_command_line.h"
#include "worker/daemon/worker_daemon.h"

namespace {

// The defaults that depend on the host, and the rlpos-sim to run, which must exist.
void CompleteOptions(rlpos::WorkerOptions& options) {
  if (options.id.empty())
    options.id = rlpos::HostName() + "-" + std::to_string(getpid());
  if (options.work_dir.empty())
    options.work_dir = "results/work/" + options.id;
  if (options.sim_binary.empty())
    options.sim_binary = rlpos::ExecutableDir() + "/rlpos-sim";
  if (!std::filesystem::exists(options.sim_binary))
    throw std::invalid_argument(options.sim_binary + ": no such file");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rlpos;
  DaemonCommandLine cli(
      "rlpos-worker",
      "rlpos-worker: runs campaign jobs (rlpos-sim) for an rlpos-coordinator over DDS",
      DdsRole::kWorker);
  CLI::App& app = cli.app();
  WorkerOptions options;
  options.slots = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--slots", options.slots, "Jobs run at once (default: the number of cores)")
      ->check(CLI::Range(1, 1024));
  app.add_option("--id", options.id, "Worker id, unique on the domain (default: host-pid)");
  app.add_option("--work-dir", options.work_dir,
                 "Folder of the jobs' files (default: results/work/<id>)");
  cli.AddDdsOptions();
  app.add_option("--sim", options.sim_binary, "rlpos-sim to run (default: the sibling binary)");
  app.add_option("--max-timeout", options.max_timeout_s,
                 "Longest job timeout accepted, seconds (default 604800: a week)")
      ->check(CLI::Range(1.0, 1e8));
  if (const auto exit_code = cli.Parse(argc, argv))
    return *exit_code;
  try {
    CompleteOptions(options);
  } catch (const std::exception& e) {
    cli.PrintError(e.what());
    return 2;
  }
  InstallStopSignalHandlers();
  return cli.Run([&] {
    WorkerDaemon daemon(options, cli.dds());
    daemon.Run();
  });
}
