// rlpos-campaign run: the embedded default. Starts rlpos-coordinator and N rlpos-workers as
// child processes on a private loopback-only DDS domain (a random discovery tag), submits the
// campaign over DDS like `submit` does, follows it in the database with a progress bar,
// restarts a daemon that dies, and at the end prints the summary and writes the report.
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <thread>

#include "common/campaign/campaign_request.h"
#include "common/campaign/expansion.h"
#include "common/process/child_process.h"
#include "common/process/executable_path.h"
#include "common/process/file_lock.h"
#include "common/process/stop_signal.h"
#include "common/process/wall_clock.h"
#include "common/scenario/number_text.h"
#include "common/store/results_reader.h"
#include "common/store/store_db.h"
#include "coordinator/cli/campaign_client.h"
#include "coordinator/cli/campaign_commands.h"
#include "coordinator/cli/crash_loop.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/progress_text.h"
#include "coordinator/reporting/report_writer.h"
#include "coordinator/reporting/results_format.h"
#include "coordinator/reporting/scenario_maps.h"

namespace rlpos {
namespace fs = std::filesystem;

namespace {

// The last non-empty line of a daemon's log, for an error message.
std::string TailOfFile(const std::string& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty())
      last = line;
  }
  return last.empty() ? "see " + file : last;
}

std::string NewTag() {
  std::random_device random;
  char tag[48];
  std::snprintf(tag, sizeof tag, "rlpos-run-%d-%08x", static_cast<int>(getpid()), random());
  return tag;
}

// A daemon of the run: its command line (per restart: a restarted worker takes a new id, so
// that the coordinator sees the old one's lease run out), its log, and restarts when it dies.
class Daemon {
 public:
  using CommandLine = std::function<std::vector<std::string>(int restart)>;
  Daemon(std::string name, CommandLine argv, std::string log)
      : name_(std::move(name)), argv_(std::move(argv)), log_(std::move(log)) {}

  void Start() {
    const std::string log = restarts_ == 0 ? log_ : log_ + "." + std::to_string(restarts_);
    process_ = std::make_unique<ChildProcess>(argv_(restarts_), "/dev/null", log);
    started_ = SteadySeconds();
  }
  // Throws if it ended (before it was ever up: no point in restarting).
  void RequireRunning() {
    if (process_ && process_->Poll()) {
      throw std::runtime_error(name_ + " ended at start-up (" + Describe(process_->exit_status()) +
                               "): " + TailOfFile(log_));
    }
  }
  // Restarts it if it ended, however often, unless it is crash-looping (then throws); returns
  // a line saying so, or "".
  std::string KeepAlive() {
    if (!process_ || !process_->Poll())
      return "";
    const std::string how = Describe(process_->exit_status());
    const ChildExit& exit = process_->exit_status();
    crash_loop_.Died(started_, SteadySeconds(),
                     !exit.exited && (exit.signal == SIGKILL || exit.signal == SIGTERM));
    if (crash_loop_.CrashLooping()) {
      throw std::runtime_error(name_ + " is crash-looping: it ended (" + how + ") " +
                               crash_loop_.Describe() + "; see " + LastLog());
    }
    ++restarts_;
    Start();
    return name_ + " ended (" + how + "); restarted (" + std::to_string(restarts_) + ")";
  }
  void Terminate() {
    if (process_)
      process_->Terminate();
  }
  void Stop(double grace_s) {
    if (process_)
      process_->Kill(grace_s);
  }

 private:
  std::string name_;
  CommandLine argv_;
  std::string log_;
  static double SteadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  std::string LastLog() const {
    return restarts_ == 0 ? log_ : log_ + "." + std::to_string(restarts_);
  }

  int restarts_ = 0;
  double started_ = 0;
  CrashLoopGuard crash_loop_;
  std::unique_ptr<ChildProcess> process_;
};

class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool enabled) : enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0) {}
  void Show(const std::string& line, bool final) {
    if (!enabled_)
      return;
    if (tty_) {
      std::cerr << "\r\033[K" << line << (final ? "\n" : "") << std::flush;
      return;
    }
    // Not a terminal (CI, a log file): a line when something changed, at most every 10 s.
    const auto now = std::chrono::steady_clock::now();
    if (!final && (line == last_ || now - last_time_ < std::chrono::seconds(10)))
      return;
    std::cerr << line << "\n";
    last_ = line;
    last_time_ = now;
  }
  void Note(const std::string& text) {
    if (tty_ && enabled_)
      std::cerr << "\r\033[K";
    std::cerr << "rlpos-campaign: " << text << "\n";
  }

 private:
  bool enabled_, tty_;
  std::string last_;
  std::chrono::steady_clock::time_point last_time_{};
};

// What a campaign would run: its id and its jobs per scenario and kind.
void PrintPlan(const CampaignPlan& campaign) {
  std::map<std::string, std::map<std::string, int>> counts;  // scenario -> kind -> jobs
  std::vector<std::string> order;
  campaign.ForEachJob([&](Job&& job) {
    if (!counts.count(job.params.scenario))
      order.push_back(job.params.scenario);
    ++counts[job.params.scenario][ToString(job.params.kind)];
  });
  std::cout << "campaign " << campaign.id << " (" << campaign.name << "): " << campaign.JobCount()
            << " jobs, " << campaign.max_attempts << " attempt(s) each at most, timeout "
            << FormatNumber(campaign.job_timeout_s) << " s\n";
  for (const auto& scenario : order) {
    auto& c = counts[scenario];
    std::cout << "  " << scenario << ": " << c["train"] << " train, " << c["position"]
              << " position, " << c["eval"] << " eval";
    if (c["track"] > 0)
      std::cout << ", " << c["track"] << " track";
    std::cout << "\n";
  }
}

using Daemons = std::vector<std::unique_ptr<Daemon>>;

// Where a run's daemons are, meet and write.
struct RunSite {
  std::string bin;  // the folder of rlpos-coordinator and rlpos-worker
  std::string tag;  // the DDS discovery tag
  DdsOptions dds;
  fs::path db_dir;
  fs::path log_dir;
};

// The private loopback domain of the run: the tag's.
DdsOptions LoopbackDds(const std::string& tag) {
  DdsOptions dds;
  dds.loopback_tag = tag;
  dds.domain = 1 + static_cast<int>(std::hash<std::string>{}(tag) % 200);
  CheckDdsOptions(dds);
  return dds;
}

// A database that cannot be opened or migrated, or that another coordinator owns, is bad
// input: say so before starting anything (the coordinator would refuse it).
void CheckDatabaseIsFree(const std::string& db) {
  { StoreDb check(db); }
  try {
    ExclusiveFileLock probe(db + ".coordinator.lock");
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(db + " is in use by another coordinator (" + e.what() +
                                "); use another --db, or `submit` to that one");
  }
}

RunSite PrepareSite(const RunOptions& options) {
  RunSite site;
  site.bin = ExecutableDir();
  // The embedded daemons stay on a private loopback tag, unsecured: an RLPOS_SECURITY meant for
  // a deployment (whose identities may not all be here) must not reach them.
  ::unsetenv("RLPOS_SECURITY");
  ::unsetenv("RLPOS_IDENTITY");
  site.tag = options.tag.empty() ? NewTag() : options.tag;
  site.dds = LoopbackDds(site.tag);
  site.db_dir = fs::absolute(options.db).parent_path();
  fs::create_directories(site.db_dir);
  CheckDatabaseIsFree(options.db);
  site.log_dir =
      options.log_dir.empty() ? site.db_dir / "logs" / site.tag : fs::path(options.log_dir);
  fs::create_directories(site.log_dir);
  return site;
}

// The coordinator first, then the workers w0, w1, ...
Daemons MakeDaemons(const RunOptions& options, const RunSite& site) {
  const auto dds_args = DdsArgs(site.dds);
  Daemons daemons;
  std::vector<std::string> coordinator{site.bin + "/rlpos-coordinator", "--db", options.db,
                                       "--log-level", "info"};
  coordinator.insert(coordinator.end(), dds_args.begin(), dds_args.end());
  daemons.push_back(std::make_unique<Daemon>(
      "rlpos-coordinator", [coordinator](int) { return coordinator; },
      (site.log_dir / "coordinator.log").string()));
  for (int i = 0; i < options.workers; ++i) {
    const std::string name = "w" + std::to_string(i);
    const auto command_line = [site, dds_args, name,
                               slots = options.slots_per_worker](int restart) {
      const std::string id =
          site.tag + "-" + name + (restart > 0 ? "." + std::to_string(restart) : "");
      std::vector<std::string> worker{site.bin + "/rlpos-worker",
                                      "--id",
                                      id,
                                      "--slots",
                                      std::to_string(slots),
                                      "--work-dir",
                                      (site.db_dir / "work" / site.tag / id).string(),
                                      "--log-level",
                                      "info"};
      worker.insert(worker.end(), dds_args.begin(), dds_args.end());
      return worker;
    };
    daemons.push_back(std::make_unique<Daemon>("rlpos-worker " + site.tag + "-" + name,
                                               command_line,
                                               (site.log_dir / (name + ".log")).string()));
  }
  return daemons;
}

// Workers first (all at once), so that the coordinator sees them stop, not get lost.
void StopDaemons(const Daemons& daemons) {
  for (std::size_t i = 1; i < daemons.size(); ++i)
    daemons[i]->Terminate();
  for (std::size_t i = 1; i < daemons.size(); ++i)
    daemons[i]->Stop(3.0);
  daemons[0]->Stop(5.0);
}

// Submits the campaign once the coordinator answers; returns its id. Throws if a daemon ends
// first, or the coordinator refuses the campaign or expands it to another one.
std::string SubmitToCoordinator(const CampaignSubmission& submission, const RunOptions& options,
                                const DdsOptions& dds, const Daemons& daemons) {
  const CampaignPlan& campaign = submission.campaign;
  const msg::CampaignReply reply =
      SendCampaignRequest(dds, SubmitRequest(submission, options.use_cache), 60.0, [&] {
        if (StopRequested())
          throw std::runtime_error("interrupted before the campaign started");
        for (auto& d : daemons)
          d->RequireRunning();
      });
  if (!reply.ok)
    throw std::runtime_error("the coordinator refused the campaign: " + reply.message);
  if (reply.campaign_id != campaign.id) {
    throw std::runtime_error("the coordinator expanded the campaign to " + reply.campaign_id +
                             ", not " + campaign.id + " (different rlpos versions?)");
  }
  return reply.campaign_id;
}

// Shows the campaign's progress until it is settled (true) or the user interrupts (false),
// restarting the daemons that end.
bool FollowUntilSettled(ResultsReader& store, const std::string& campaign_id,
                        const Daemons& daemons, ProgressPrinter& printer) {
  for (;;) {
    if (StopRequested())
      return false;
    for (auto& d : daemons) {
      const std::string note = d->KeepAlive();
      if (!note.empty())
        printer.Note(note);
    }
    const CampaignProgress progress = store.Progress(campaign_id);
    const bool settled = IsSettled(progress);
    const auto eta =
        EstimateRemainingSeconds(progress, store.Timing(campaign_id), WallClockSeconds());
    printer.Show(ProgressLine(progress, settled ? std::nullopt : eta), settled);
    if (settled)
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
}

// The summary tables, the report and the failed jobs of a settled campaign; returns the exit
// code.
int PrintOutcome(ResultsReader& store, const std::string& campaign_id, const RunOptions& options,
                 const RunSite& site, ProgressPrinter& printer) {
  const CampaignProgress progress = store.Progress(campaign_id);
  std::cout << ResultsTables(store, campaign_id);
  const std::string report_dir = options.report_dir.empty()
                                     ? (site.db_dir / "reports" / campaign_id).string()
                                     : options.report_dir;
  ReportOptions report_options;
  report_options.plot_script = DefaultPlotScript(site.bin);
  report_options.render_program = DefaultRenderProgram(site.bin);
  const ReportResult report = WriteReport(store, campaign_id, report_dir, report_options);
  for (const auto& w : report.warnings)
    printer.Note("warning: " + w);
  std::cout << "report: " << report_dir << "\n";
  for (const auto& f : store.FailedJobs(campaign_id)) {
    printer.Note("failed: " + f.key + " after " + std::to_string(f.attempts) +
                 " attempt(s): " + f.error);
  }
  return progress.failed > 0 ? kExitJobsFailed : kExitOk;
}

}  // namespace

int RunCampaign(const RunOptions& options) {
  // Bad input stops here, before anything starts.
  const CampaignSubmission submission = ReadCampaignSubmission(options.campaign_file);
  const CampaignPlan& campaign = submission.campaign;
  if (options.dry_run) {
    PrintPlan(campaign);
    return kExitOk;
  }
  const RunSite site = PrepareSite(options);
  const Daemons daemons = MakeDaemons(options, site);
  ProgressPrinter printer(options.progress);
  try {
    for (auto& d : daemons)
      d->Start();
    printer.Note("running " + campaign.name + " (" + std::to_string(campaign.JobCount()) +
                 " jobs) on " + std::to_string(options.workers) + " worker(s); " +
                 DescribeDds(site.dds) + "; logs in " + site.log_dir.string());
    const std::string campaign_id = SubmitToCoordinator(submission, options, site.dds, daemons);
    std::cout << "campaign " << campaign_id << "\n" << std::flush;

    StoreOptions read_only;
    read_only.read_only = true;
    StoreDb opened(options.db, read_only);
    ResultsReader store(opened);
    if (!FollowUntilSettled(store, campaign_id, daemons, printer)) {
      StopDaemons(daemons);
      printer.Note("interrupted; run the same command again to resume");
      return kExitInterrupted;
    }
    StopDaemons(daemons);
    return PrintOutcome(store, campaign_id, options, site, printer);
  } catch (...) {
    StopDaemons(daemons);
    throw;
  }
}

}  // namespace rlpos
