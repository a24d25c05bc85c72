#pragma once
// The subcommands of rlpos-campaign. Each returns the process exit code; errors are thrown
// (rlpos_campaign.cc turns them into one line and the code below).
#include <string>

#include "common/campaign/expansion.h"
#include "common/store/results_reader.h"
#include "idl/dds/dds_config.h"

namespace rlpos {

// Exit codes of rlpos-campaign.
enum ExitCode {
  kExitOk = 0,
  kExitFailure = 1,        // runtime failure (a daemon would not start, I/O, DDS)
  kExitBadInput = 2,       // usage, campaign file, database, unknown campaign id
  kExitJobsFailed = 3,     // run: the campaign finished but some jobs failed
  kExitNoCoordinator = 4,  // submit, cancel, retry: no coordinator answered
  kExitInterrupted = 130,  // run: stopped by SIGINT/SIGTERM (resume with the same command)
};

struct RunOptions {
  std::string campaign_file;
  int workers = 1;
  int slots_per_worker = 1;
  std::string db = "results/rlpos.db";
  std::string report_dir;  // default results/reports/<campaign id>
  bool progress = true;    // redraw a progress bar (a TTY) or print a line now and then
  std::string tag;         // DDS discovery tag; default: random (rlpos-run-<pid>-<hex>)
  bool dry_run = false;    // print the campaign id and its jobs by scenario and kind; run nothing
  std::string log_dir;     // default results/logs/<tag>
  bool use_cache = true;   // false: every job runs, none takes a cached result (--no-cache)
};

int RunCampaign(const RunOptions& options);
int SubmitCampaign(const std::string& campaign_file, bool use_cache, const DdsOptions& dds,
                   double timeout_s);
int CancelCampaign(const std::string& campaign_id, const DdsOptions& dds, double timeout_s);
int RetryCampaign(const std::string& campaign_id, const DdsOptions& dds, double timeout_s);
int ShowStatus(const std::string& db, const std::string& campaign_id, bool watch, double period_s);
// Which results `results` shows: the summary per scenario and positioner (the table format
// adds the others that have rows), or only the per-UAV, optimality or track one.
enum class ResultsView { kSummary, kPerUav, kOptimality, kTrack };
int ShowResults(const std::string& db, const std::string& campaign_id, const std::string& format,
                ResultsView view);
// The summary table, then the per-UAV one when the campaign has scenarios of several UAVs, the
// optimality one when a scenario has rl and oracle rewards (reporting/optimality.h), and the
// track one when it has track runs (reporting/track_summary.h).
std::string ResultsTables(ResultsReader& store, const std::string& campaign_id);
// security init DIR; security add-worker|add-client DIR NAME.
int InitSecurity(const std::string& dir, int days);
int AddSecurityIdentity(const std::string& dir, const std::string& name, DdsRole role, int days);
// Lists the artifacts of a campaign or job, or (out_dir given) exports them to
// out_dir/<job key>/<name>, checked against their sha256; out_dir must not exist.
int ListOrExportArtifacts(const std::string& db, const std::string& id, const std::string& out_dir);
int WriteCampaignReport(const std::string& db, const std::string& campaign_id,
                        const std::string& out_dir);

}  // namespace rlpos
