// rlpos-coordinator: owns the results database and runs campaigns on the workers that announce
// themselves on DDS. Restart it at any time: its state is the database.
//   rlpos-coordinator [--db FILE] [--domain N] [--loopback TAG | --dds-config XML_OR_FILE]
//                     [--log-level L]
// Exit codes: 0 stopped by SIGTERM/SIGINT, 1 runtime failure (database, DDS), 2 bad input.
#include <filesystem>

#include "common/process/stop_signal.h"
#include "coordinator/daemon/coordinator_daemon.h"
#include "idl/dds/daemon_command_line.h"

int main(int argc, char** argv) {
  using namespace rlpos;
  DaemonCommandLine cli("rlpos-coordinator",
                        "rlpos-coordinator: assigns campaign jobs to rlpos-workers over DDS and "
                        "keeps the results in SQLite",
                        DdsRole::kCoordinator);
  CLI::App& app = cli.app();
  CoordinatorOptions options;
  options.db_file = "results/rlpos.db";
  app.add_option("--db", options.db_file, "Results database (default: results/rlpos.db)");
  cli.AddDdsOptions();
  app.add_option("--grace", options.restart_grace_s,
                 "Seconds to wait for workers after a start before requeuing their jobs")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--max-jobs", options.limits.max_jobs,
                 "Largest campaign a submit may expand to (default 200000)")
      ->check(CLI::Range(1, 10000000));
  app.add_option("--max-infra-losses", options.max_infra_losses,
                 "Times a job may be lost with its worker (not using its retries) before it "
                 "fails (default 10)")
      ->check(CLI::Range(0, 1000000));
  if (const auto exit_code = cli.Parse(argc, argv))
    return *exit_code;
  InstallStopSignalHandlers();
  return cli.Run([&] {
    const auto folder = std::filesystem::path(options.db_file).parent_path();
    if (!folder.empty())
      std::filesystem::create_directories(folder);
    CoordinatorDaemon daemon(options, cli.dds());
    daemon.Run();
  });
}
