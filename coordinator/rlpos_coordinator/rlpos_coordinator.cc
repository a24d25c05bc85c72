// rlpos-coordinator: owns the results database and runs campaigns on the workers that announce
// themselves on DDS. Restart it at any time: its state is the database.
//   rlpos-coordinator [--db FILE] [--domain N] [--loopback TAG | --dds-config XML_OR_FILE]
//                     [--log-level L]
// Exit codes: 0 stopped by SIGTERM/SIGINT, 1 runtime failure (database, DDS), 2 bad input.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "coordinator/daemon/coordinator_daemon.h"
#include "idl/dds/dds_cli_options.h"
#include "idl/dds/participant.h"
#include "idl/dds/security/security_check.h"
#include "common/logging/log.h"
#include "common/process/stop_signal.h"

int main(int argc, char** argv) {
  using namespace rlpos;
  CLI::App app{
      "rlpos-coordinator: assigns campaign jobs to rlpos-workers over DDS and keeps "
      "the results in SQLite"};
  CoordinatorOptions options;
  options.db_file = "results/rlpos.db";
  DdsOptions dds;
  dds.role = DdsRole::kCoordinator;
  std::string log_level = "info";
  app.add_option("--db", options.db_file, "Results database (default: results/rlpos.db)");
  AddDdsOptions(&app, dds);
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
  } catch (const std::exception& e) {
    std::cerr << "rlpos-coordinator: error: " << e.what() << "\n";
    return 2;
  }
  InstallStopSignalHandlers();
  try {
    const auto folder = std::filesystem::path(options.db_file).parent_path();
    if (!folder.empty())
      std::filesystem::create_directories(folder);
    CoordinatorDaemon daemon(options, dds);
    daemon.Run();
  } catch (const security::SecuritySetupError& e) {
    // A bad identity is bad input, like a bad flag.
    std::cerr << "rlpos-coordinator: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rlpos-coordinator: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
