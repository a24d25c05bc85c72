// rlpos-campaign: run the paper's experiment campaigns and read their results.
//   run CAMPAIGN.json [--workers N] [--db FILE]   embedded coordinator + N workers (loopback)
//   submit CAMPAIGN.json                          to a running rlpos-coordinator (DDS)
//   status [ID] [--watch] [--db FILE]             jobs by state, workers, progress, ETA
//   results ID [--format table|csv|json] [--per-uav|--optimality|--track] [--db FILE]
//   report ID --out DIR [--db FILE]
//   cancel ID | retry ID                          via the coordinator (DDS)
//   serve [--db FILE] [--listen ADDR:PORT] [--token-file F]   the campaign page (read-only)
//   security init DIR | add-worker DIR NAME | add-client DIR NAME   DDS Security identities
// Exit codes: see ExitCode in campaign_commands.h (0 ok, 1 failure, 2 bad input, 3 some jobs
// failed, 4 no coordinator answered, 130 interrupted).
#include <CLI/CLI.hpp>
#include <iostream>
#include <thread>

#include "common/command_line/parse_error.h"
#include "common/command_line/version_flag.h"
#include "common/config/config_error.h"
#include "common/process/stop_signal.h"
#include "common/store/store_error.h"
#include "coordinator/cli/campaign_client.h"
#include "coordinator/cli/campaign_commands.h"
#include "coordinator/web/serve_command.h"
#include "idl/dds/dds_cli_options.h"
#include "idl/dds/participant.h"
#include "idl/dds/security/security_check.h"

namespace rlpos {
namespace {

const char* const kNoCacheHelp =
    "Run every job, even one whose result the database already holds from an identical job";

// What the command line gives, and the subcommands to ask which one was parsed. Subcommands
// share a value where they take the same flag (--db, the campaign id, the DDS flags).
struct CommandLine {
  std::string db = "results/rlpos.db";
  RunOptions run_options;
  std::string campaign_file, campaign_id, format = "table", out_dir, artifacts_out;
  bool use_cache = true, watch = false, per_uav = false, optimality = false, track = false;
  double period_s = 2;
  DdsOptions dds;
  double timeout_s = 10;
  std::string security_dir, identity_name;
  int days = 365;
  web::ServeOptions serve_options;

  CLI::App *run = nullptr, *submit = nullptr, *status = nullptr, *results = nullptr,
           *report = nullptr, *artifacts = nullptr, *cancel = nullptr, *retry = nullptr,
           *security_init = nullptr, *add_worker = nullptr, *add_client = nullptr, *serve = nullptr;
};

void AddDbOption(CLI::App* command, std::string& db) {
  command->add_option("--db", db, "Results database (default: results/rlpos.db)");
}

void AddRequestOptions(CLI::App* command, DdsOptions& dds, double& timeout_s) {
  AddDdsOptions(command, dds);
  command->add_option("--timeout", timeout_s, "Seconds to wait for the coordinator (default 10)")
      ->check(CLI::PositiveNumber);
}

void AddRunCommand(CLI::App& app, CommandLine& cli) {
  RunOptions& options = cli.run_options;
  options.workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  auto* run = app.add_subcommand("run", "Run a campaign here: coordinator + workers on loopback");
  run->add_option("campaign", options.campaign_file, "Campaign JSON")->required();
  run->add_option("--workers", options.workers, "Local workers (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  run->add_option("--slots", options.slots_per_worker, "Jobs per worker at once (default 1)")
      ->check(CLI::Range(1, 256));
  AddDbOption(run, cli.db);
  run->add_option("--report", options.report_dir,
                  "Report folder (default: reports/<campaign id> next to the database)");
  run->add_option("--tag", options.tag, "DDS discovery tag (default: a random one)");
  run->add_flag("!--no-progress", options.progress, "No progress bar");
  run->add_flag("--dry-run", options.dry_run,
                "Print the campaign id and its jobs per scenario; run nothing");
  run->add_flag("!--no-cache", options.use_cache, kNoCacheHelp);
  cli.run = run;
}

void AddSubmitCommand(CLI::App& app, CommandLine& cli) {
  auto* submit = app.add_subcommand("submit", "Submit a campaign to a running coordinator");
  submit->add_option("campaign", cli.campaign_file, "Campaign JSON")->required();
  submit->add_flag("!--no-cache", cli.use_cache, kNoCacheHelp);
  AddRequestOptions(submit, cli.dds, cli.timeout_s);
  cli.submit = submit;
}

// status, results, report, artifacts and serve: they read the database.
void AddReadCommands(CLI::App& app, CommandLine& cli) {
  auto* status = app.add_subcommand("status", "Jobs by state, workers alive, progress and ETA");
  status->add_option("id", cli.campaign_id, "Campaign id (default: every campaign)");
  status->add_flag("--watch", cli.watch, "Refresh until the campaigns are settled");
  status->add_option("--period", cli.period_s, "Seconds between refreshes (default 2)")
      ->check(CLI::PositiveNumber);
  AddDbOption(status, cli.db);

  auto* results = app.add_subcommand("results", "Per scenario and positioner: median, mean, CI");
  results->add_option("id", cli.campaign_id, "Campaign id")->required();
  results->add_option("--format", cli.format, "table|csv|json (default table)")
      ->check(CLI::IsMember({"table", "csv", "json"}));
  results->add_flag("--per-uav", cli.per_uav,
                    "Per UAV of the scenarios with several (the table shows both by default)");
  results
      ->add_flag("--optimality", cli.optimality,
                 "rl's reward over the oracle's per algorithm and UAV count (also in the table)")
      ->excludes("--per-uav");
  results
      ->add_flag("--track", cli.track,
                 "The track runs: per scenario and positioner, each metric's mean over the "
                 "RngRuns (also in the table)")
      ->excludes("--per-uav")
      ->excludes("--optimality");
  AddDbOption(results, cli.db);

  auto* report = app.add_subcommand("report", "Write CSV, Markdown and PNG plots of a campaign");
  report->add_option("id", cli.campaign_id, "Campaign id")->required();
  report->add_option("--out", cli.out_dir, "Report folder")->required();
  AddDbOption(report, cli.db);

  auto* artifacts = app.add_subcommand(
      "artifacts", "List a campaign's (or a job's) artifacts: policies, learning curves, ...");
  artifacts->add_option("id", cli.campaign_id, "Campaign id or job id")->required();
  artifacts->add_option("--out", cli.artifacts_out,
                        "Export them to this new folder, as <job key>/<name>");
  AddDbOption(artifacts, cli.db);
  auto* serve = app.add_subcommand("serve", "The campaign page in a browser (read-only)");
  AddDbOption(serve, cli.db);
  serve->add_option("--listen", cli.serve_options.listen,
                    "Address and port (default 127.0.0.1:8787; another than the loopback needs "
                    "--token-file)");
  serve->add_option("--token-file", cli.serve_options.token_file,
                    "File whose first line is the token every request must carry");
  cli.serve = serve;
  cli.status = status;
  cli.results = results;
  cli.report = report;
  cli.artifacts = artifacts;
}

// cancel and retry: requests to the coordinator.
void AddRequestCommands(CLI::App& app, CommandLine& cli) {
  cli.cancel = app.add_subcommand("cancel", "Cancel a campaign's unfinished jobs");
  cli.cancel->add_option("id", cli.campaign_id, "Campaign id")->required();
  AddRequestOptions(cli.cancel, cli.dds, cli.timeout_s);
  cli.retry = app.add_subcommand("retry", "Run a campaign's failed jobs again");
  cli.retry->add_option("id", cli.campaign_id, "Campaign id")->required();
  AddRequestOptions(cli.retry, cli.dds, cli.timeout_s);
}

void AddSecurityCommands(CLI::App& app, CommandLine& cli) {
  auto* security = app.add_subcommand("security", "Make DDS Security identities (CA, permissions)");
  security->require_subcommand(1);
  cli.security_init = security->add_subcommand("init",
                                               "New folder: a CA, governance, and identities "
                                               "coordinator, worker and client");
  cli.security_init->add_option("dir", cli.security_dir, "Folder to create")->required();
  cli.add_worker = security->add_subcommand("add-worker", "Issue one more worker identity");
  cli.add_client = security->add_subcommand("add-client", "Issue one more client identity");
  for (auto* command : {cli.add_worker, cli.add_client}) {
    command->add_option("dir", cli.security_dir, "Folder made by `security init`")->required();
    command->add_option("name", cli.identity_name, "Identity name (use it with --identity)")
        ->required();
  }
  for (auto* command : {cli.security_init, cli.add_worker, cli.add_client}) {
    command->add_option("--days", cli.days, "Identities valid this many days (default 365)")
        ->check(CLI::Range(1, 36500));
  }
}

// Runs the parsed subcommand; returns its exit code.
int RunCommand(CommandLine& cli) {
  if (cli.submit->parsed() || cli.cancel->parsed() || cli.retry->parsed())
    PreflightDds(cli.dds);
  InstallStopSignalHandlers();
  if (cli.security_init->parsed())
    return InitSecurity(cli.security_dir, cli.days);
  if (cli.add_worker->parsed())
    return AddSecurityIdentity(cli.security_dir, cli.identity_name, DdsRole::kWorker, cli.days);
  if (cli.add_client->parsed())
    return AddSecurityIdentity(cli.security_dir, cli.identity_name, DdsRole::kClient, cli.days);
  if (cli.run->parsed()) {
    cli.run_options.db = cli.db;
    return RunCampaign(cli.run_options);
  }
  if (cli.submit->parsed())
    return SubmitCampaign(cli.campaign_file, cli.use_cache, cli.dds, cli.timeout_s);
  if (cli.status->parsed())
    return ShowStatus(cli.db, cli.campaign_id, cli.watch, cli.period_s);
  if (cli.results->parsed())
    return ShowResults(cli.db, cli.campaign_id, cli.format,
                       cli.track        ? ResultsView::kTrack
                       : cli.optimality ? ResultsView::kOptimality
                       : cli.per_uav    ? ResultsView::kPerUav
                                        : ResultsView::kSummary);
  if (cli.report->parsed())
    return WriteCampaignReport(cli.db, cli.campaign_id, cli.out_dir);
  if (cli.artifacts->parsed())
    return ListOrExportArtifacts(cli.db, cli.campaign_id, cli.artifacts_out);
  if (cli.serve->parsed()) {
    cli.serve_options.db = cli.db;
    web::RunServe(cli.serve_options);
    return kExitOk;
  }
  if (cli.cancel->parsed())
    return CancelCampaign(cli.campaign_id, cli.dds, cli.timeout_s);
  if (cli.retry->parsed())
    return RetryCampaign(cli.campaign_id, cli.dds, cli.timeout_s);
  return kExitFailure;
}

// Says `e` on one line of stderr; returns `exit_code`.
int Fail(const std::exception& e, int exit_code) {
  std::cerr << "rlpos-campaign: error: " << e.what() << "\n";
  return exit_code;
}

// RunCommand, with its errors said on one line and mapped to the exit codes.
int RunCommandReportingErrors(CommandLine& cli) {
  try {
    return RunCommand(cli);
  } catch (const ConfigError& e) {
    const std::string& file = cli.run->parsed() ? cli.run_options.campaign_file : cli.campaign_file;
    std::cerr << "rlpos-campaign: error: " << file << ": " << e.describe() << "\n";
    return kExitBadInput;
  } catch (const StoreError& e) {
    return Fail(e, kExitBadInput);
  } catch (const std::invalid_argument& e) {
    return Fail(e, kExitBadInput);
  } catch (const security::SecuritySetupError& e) {
    return Fail(e, kExitBadInput);
  } catch (const NoCoordinatorError& e) {
    return Fail(e, kExitNoCoordinator);
  } catch (const std::exception& e) {
    return Fail(e, kExitFailure);
  }
}

}  // namespace
}  // namespace rlpos

int main(int argc, char** argv) {
  using namespace rlpos;
  CLI::App app{"rlpos-campaign: run RLpos experiment campaigns and read their results"};
  app.require_subcommand(1);
  AddVersionFlag(app, "rlpos-campaign");
  CommandLine cli;
  cli.dds.role = DdsRole::kClient;
  AddRunCommand(app, cli);
  AddSubmitCommand(app, cli);
  AddReadCommands(app, cli);
  AddRequestCommands(app, cli);
  AddSecurityCommands(app, cli);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return ExitOnParseError(app, "rlpos-campaign", e, kExitBadInput);
  }
  return RunCommandReportingErrors(cli);
}
