// rlpos-campaign: run the paper's experiment campaigns and read their results.
//   run CAMPAIGN.json [--workers N] [--db FILE]   embedded coordinator + N workers (loopback)
//   submit CAMPAIGN.json                          to a running rlpos-coordinator (DDS)
//   status [ID] [--watch] [--db FILE]             jobs by state, workers, progress, ETA
//   results ID [--format table|csv|json] [--per-uav] [--db FILE]
//   report ID --out DIR [--db FILE]
//   cancel ID | retry ID                          via the coordinator (DDS)
//   security init DIR | add-worker DIR NAME | add-client DIR NAME   DDS Security identities
// Exit codes: see ExitCode in campaign_commands.h (0 ok, 1 failure, 2 bad input, 3 some jobs
// failed, 4 no coordinator answered, 130 interrupted).
#include <CLI/CLI.hpp>
#include <iostream>
#include <thread>

#include "coordinator/cli/campaign_client.h"
#include "coordinator/cli/campaign_commands.h"
#include "common/config/config_error.h"
#include "idl/dds/dds_cli_options.h"
#include "idl/dds/participant.h"
#include "idl/dds/security/security_check.h"
#include "common/process/stop_signal.h"
#include "common/store/store_error.h"

namespace {

void AddRequestOptions(CLI::App* command, rlpos::DdsOptions& dds, double& timeout_s) {
  rlpos::AddDdsOptions(command, dds);
  command->add_option("--timeout", timeout_s, "Seconds to wait for the coordinator (default 10)")
      ->check(CLI::PositiveNumber);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rlpos;
  CLI::App app{"rlpos-campaign: run RLpos experiment campaigns and read their results"};
  app.require_subcommand(1);
  std::string db = "results/rlpos.db";
  const auto add_db = [&db](CLI::App* command) {
    command->add_option("--db", db, "Results database (default: results/rlpos.db)");
  };

  RunOptions run_options;
  run_options.workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  auto* run = app.add_subcommand("run", "Run a campaign here: coordinator + workers on loopback");
  run->add_option("campaign", run_options.campaign_file, "Campaign JSON")->required();
  run->add_option("--workers", run_options.workers, "Local workers (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  run->add_option("--slots", run_options.slots_per_worker, "Jobs per worker at once (default 1)")
      ->check(CLI::Range(1, 256));
  add_db(run);
  run->add_option("--report", run_options.report_dir,
                  "Report folder (default: reports/<campaign id> next to the database)");
  run->add_option("--tag", run_options.tag, "DDS discovery tag (default: a random one)");
  run->add_flag("!--no-progress", run_options.progress, "No progress bar");
  run->add_flag("--dry-run", run_options.dry_run,
                "Print the campaign id and its jobs per scenario; run nothing");
  const char* const no_cache_help =
      "Run every job, even one whose result the database already holds from an identical job";
  run->add_flag("!--no-cache", run_options.use_cache, no_cache_help);

  std::string campaign_file, campaign_id, format = "table", out_dir;
  DdsOptions dds;
  dds.role = DdsRole::kClient;
  double timeout_s = 10;
  auto* submit = app.add_subcommand("submit", "Submit a campaign to a running coordinator");
  submit->add_option("campaign", campaign_file, "Campaign JSON")->required();
  bool use_cache = true;
  submit->add_flag("!--no-cache", use_cache, no_cache_help);
  AddRequestOptions(submit, dds, timeout_s);

  bool watch = false;
  bool per_uav = false;
  double period_s = 2;
  auto* status = app.add_subcommand("status", "Jobs by state, workers alive, progress and ETA");
  status->add_option("id", campaign_id, "Campaign id (default: every campaign)");
  status->add_flag("--watch", watch, "Refresh until the campaigns are settled");
  status->add_option("--period", period_s, "Seconds between refreshes (default 2)")
      ->check(CLI::PositiveNumber);
  add_db(status);

  auto* results = app.add_subcommand("results", "Per scenario and positioner: median, mean, CI");
  results->add_option("id", campaign_id, "Campaign id")->required();
  results->add_option("--format", format, "table|csv|json (default table)")
      ->check(CLI::IsMember({"table", "csv", "json"}));
  results->add_flag("--per-uav", per_uav,
                    "Per UAV of the scenarios with several (the table shows both by default)");
  add_db(results);

  auto* report = app.add_subcommand("report", "Write CSV, Markdown and PNG plots of a campaign");
  report->add_option("id", campaign_id, "Campaign id")->required();
  report->add_option("--out", out_dir, "Report folder")->required();
  add_db(report);

  std::string artifacts_out;
  auto* artifacts = app.add_subcommand(
      "artifacts", "List a campaign's (or a job's) artifacts: policies, learning curves, ...");
  artifacts->add_option("id", campaign_id, "Campaign id or job id")->required();
  artifacts->add_option("--out", artifacts_out,
                        "Export them to this new folder, as <job key>/<name>");
  add_db(artifacts);

  auto* cancel = app.add_subcommand("cancel", "Cancel a campaign's unfinished jobs");
  cancel->add_option("id", campaign_id, "Campaign id")->required();
  AddRequestOptions(cancel, dds, timeout_s);
  auto* retry = app.add_subcommand("retry", "Run a campaign's failed jobs again");
  retry->add_option("id", campaign_id, "Campaign id")->required();
  AddRequestOptions(retry, dds, timeout_s);

  std::string security_dir, identity_name;
  int days = 365;
  auto* security = app.add_subcommand("security", "Make DDS Security identities (CA, permissions)");
  security->require_subcommand(1);
  auto* security_init = security->add_subcommand("init",
                                                 "New folder: a CA, governance, and identities "
                                                 "coordinator, worker and client");
  security_init->add_option("dir", security_dir, "Folder to create")->required();
  auto* add_worker = security->add_subcommand("add-worker", "Issue one more worker identity");
  auto* add_client = security->add_subcommand("add-client", "Issue one more client identity");
  for (auto* command : {add_worker, add_client}) {
    command->add_option("dir", security_dir, "Folder made by `security init`")->required();
    command->add_option("name", identity_name, "Identity name (use it with --identity)")
        ->required();
  }
  for (auto* command : {security_init, add_worker, add_client}) {
    command->add_option("--days", days, "Identities valid this many days (default 365)")
        ->check(CLI::Range(1, 36500));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitBadInput;
  }
  const std::string file = run->parsed() ? run_options.campaign_file : campaign_file;
  try {
    if (submit->parsed() || cancel->parsed() || retry->parsed())
      PreflightDds(dds);
    InstallStopSignalHandlers();
    if (security_init->parsed())
      return InitSecurity(security_dir, days);
    if (add_worker->parsed())
      return AddSecurityIdentity(security_dir, identity_name, DdsRole::kWorker, days);
    if (add_client->parsed())
      return AddSecurityIdentity(security_dir, identity_name, DdsRole::kClient, days);
    if (run->parsed()) {
      run_options.db = db;
      return RunCampaign(run_options);
    }
    if (submit->parsed())
      return SubmitCampaign(campaign_file, use_cache, dds, timeout_s);
    if (status->parsed())
      return ShowStatus(db, campaign_id, watch, period_s);
    if (results->parsed())
      return ShowResults(db, campaign_id, format, per_uav);
    if (report->parsed())
      return WriteCampaignReport(db, campaign_id, out_dir);
    if (artifacts->parsed())
      return ListOrExportArtifacts(db, campaign_id, artifacts_out);
    if (cancel->parsed())
      return CancelCampaign(campaign_id, dds, timeout_s);
    if (retry->parsed())
      return RetryCampaign(campaign_id, dds, timeout_s);
  } catch (const ConfigError& e) {
    std::cerr << "rlpos-campaign: error: " << file << ": " << e.describe() << "\n";
    return kExitBadInput;
  } catch (const StoreError& e) {
    std::cerr << "rlpos-campaign: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "rlpos-campaign: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const security::SecuritySetupError& e) {
    std::cerr << "rlpos-campaign: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const NoCoordinatorError& e) {
    std::cerr << "rlpos-campaign: error: " << e.what() << "\n";
    return kExitNoCoordinator;
  } catch (const std::exception& e) {
    std::cerr << "rlpos-campaign: error: " << e.what() << "\n";
    return kExitFailure;
  }
  return kExitFailure;
}
