// rlpos-worker: a headless worker of the campaign runner. It announces itself on DDS, runs the
// jobs the coordinator gives it in child rlpos-sim processes, and reports their results.
//   rlpos-worker [--slots N] [--id ID] [--work-dir DIR] [--domain N]
//                [--loopback TAG | --dds-config XML_OR_FILE] [--log-level L]
// Exit codes: 0 stopped by SIGTERM/SIGINT, 1 runtime failure (DDS), 2 bad input.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <thread>

#include "worker/daemon/worker_daemon.h"
#include "idl/dds/dds_cli_options.h"
#include "idl/dds/participant.h"
#include "idl/dds/security/security_check.h"
#include "common/logging/log.h"
#include "common/process/executable_path.h"
#include "common/process/host_name.h"
#include "common/process/stop_signal.h"

int main(int argc, char** argv) {
  using namespace rlpos;
  CLI::App app{"rlpos-worker: runs campaign jobs (rlpos-sim) for an rlpos-coordinator over DDS"};
  WorkerOptions options;
  DdsOptions dds;
  dds.role = DdsRole::kWorker;
  std::string log_level = "info";
  options.slots = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--slots", options.slots, "Jobs run at once (default: the number of cores)")
      ->check(CLI::Range(1, 1024));
  app.add_option("--id", options.id, "Worker id, unique on the domain (default: host-pid)");
  app.add_option("--work-dir", options.work_dir,
                 "Folder of the jobs' files (default: results/work/<id>)");
  AddDdsOptions(&app, dds);
  app.add_option("--sim", options.sim_binary, "rlpos-sim to run (default: the sibling binary)");
  app.add_option("--max-timeout", options.max_timeout_s,
                 "Longest job timeout accepted, seconds (default 604800: a week)")
      ->check(CLI::Range(1.0, 1e8));
  app.add_option("--log-level", log_level, "error|warning|info|debug")
      ->check(CLI::IsMember({"error", "warning", "info", "debug"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    SetLogLevel(ParseLogLevel(log_level));
    PreflightDds(dds);
    if (options.id.empty())
      options.id = HostName() + "-" + std::to_string(getpid());
    if (options.work_dir.empty())
      options.work_dir = "results/work/" + options.id;
    if (options.sim_binary.empty())
      options.sim_binary = ExecutableDir() + "/rlpos-sim";
    if (!std::filesystem::exists(options.sim_binary)) {
      std::cerr << "rlpos-worker: error: " << options.sim_binary << ": no such file\n";
      return 2;
    }
  } catch (const std::exception& e) {
    std::cerr << "rlpos-worker: error: " << e.what() << "\n";
    return 2;
  }
  InstallStopSignalHandlers();
  try {
    WorkerDaemon daemon(options, dds);
    daemon.Run();
  } catch (const security::SecuritySetupError& e) {
    // A bad identity is bad input, like a bad flag.
    std::cerr << "rlpos-worker: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rlpos-worker: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
