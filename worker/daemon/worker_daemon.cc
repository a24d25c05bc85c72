#include "daemon/worker_daemon.h"

#include <unistd.h>

#include <chrono>

#include "dds/topics.h"
#include "dds/wait_set.h"
#include "logging/log.h"
#include "process/host_name.h"
#include "process/stop_signal.h"
#include "wire/identifiers.h"
#include "wire/limits.h"

namespace rlpos {

struct WorkerDaemon::Endpoints {
  explicit Endpoints(Participant& p) : status(p), assignments(p), events(p), wait_set(p) {
    wait_set.Attach(assignments.handle());
  }
  Writer<msg::WorkerStatus> status;
  Reader<msg::JobAssignment> assignments;
  Writer<msg::JobEvent> events;
  WaitSet wait_set;
};

WorkerDaemon::WorkerDaemon(WorkerOptions options, const DdsOptions& dds)
    : options_(std::move(options)),
      build_(ThisBuild()),
      participant_(dds),
      dds_(std::make_unique<Endpoints>(participant_)) {
  build_.host = HostName();
}

WorkerDaemon::~WorkerDaemon() = default;

void WorkerDaemon::PublishStatus() {
  msg::WorkerStatus status;
  status.worker_id = options_.id;
  status.host = HostName();
  status.pid = getpid();
  status.slots = options_.slots;
  status.busy = static_cast<int>(running_.size());
  for (const auto& [id, job] : running_)
    status.jobs.push_back(job->Key());
  dds_->status.Write(status);
}

void WorkerDaemon::Settle(const std::string& job_id) {
  const auto it = running_.find(job_id);
  if (it != running_.end()) {
    Log(LogLevel::kInfo, "stopping " + it->second->Key() + " (withdrawn by the coordinator)");
    it->second->Stop();
    running_.erase(it);
  }
  progress_sent_.erase(job_id);
  taken_.erase(job_id);
  if (announced_.erase(job_id)) {
    msg::JobEvent key;
    key.job_id = job_id;
    dds_->events.Unregister(key);
  }
}

bool WorkerDaemon::FromCoordinator(const std::string& sender) {
  if (sender.empty())
    return false;
  if (coordinator_ == sender)
    return true;
  if (!coordinator_.empty() && dds_->assignments.HasMatchedWriterOf(coordinator_))
    return false;
  if (!coordinator_.empty())
    Log(LogLevel::kInfo, "following a new coordinator " + sender);
  coordinator_ = sender;
  return true;
}

void WorkerDaemon::Start(msg::JobAssignment a) {
  const std::string job_id = a.order.job_id;
  const int attempt = a.order.attempt;
  const std::string key = job_id + "#" + std::to_string(attempt);
  if (const auto it = running_.find(job_id); it != running_.end()) {
    // A newer attempt of a job we still run: the old one is out of date.
    it->second->Stop();
    running_.erase(it);
  }
  taken_[job_id] = attempt;
  msg::JobEvent event;
  event.job_id = job_id;
  event.attempt = attempt;
  event.worker_id = options_.id;
  try {
    if (static_cast<int>(running_.size()) >= options_.slots) {
      throw std::runtime_error("no free slot (" + std::to_string(options_.slots) + " busy)");
    }
    // Checked before anything is written: a bad order leaves no trace but the event.
    CheckedOrder checked;
    try {
      checked = CheckJobOrder(a.order, options_.max_timeout_s);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("invalid job: ") + e.what());
    }
    running_[job_id] = std::make_unique<JobAttempt>(std::move(a.order), checked.scenario,
                                                    options_.work_dir, options_.sim_binary);
    // No event for a start: the coordinator marked the job running when it assigned it, and
    // one sample fewer per job is the coordinator's time.
    Log(LogLevel::kInfo, "started " + key);
    return;
  } catch (const std::exception& e) {
    event.state = msg::JobState::kFailed;
    event.message = std::string("worker could not start the job: ") + e.what();
    event.message = event.message.substr(0, wire::kMaxMessage - 1);
    Log(LogLevel::kWarning, key + ": " + event.message);
    // Said once and forgotten: a refused order keeps no state here (its event instance is
    // unregistered at once).
    taken_.erase(job_id);
    announced_.erase(job_id);
    dds_->events.Write(event);
    dds_->events.Unregister(event);
  }
}

void WorkerDaemon::TakeAssignments() {
  bool changed = false;
  // Assignments from a coordinator this worker does not follow (yet) wait: after a coordinator
  // restart the new one can publish before the old one's writer is gone (its lease), and its
  // jobs must not be lost. They run once it is the one followed, or go after a while.
  const auto now = std::chrono::steady_clock::now();
  std::map<std::string, PendingAssignment> waiting;
  waiting.swap(pending_);
  for (auto& [job_id, p] : waiting) {
    if (FromCoordinator(p.sender)) {
      Consider(std::move(p.assignment));
    } else if (now - p.since < kPendingFor) {
      pending_.emplace(job_id, std::move(p));
    } else {
      dropped_.Drop(p.sender, "not the coordinator this worker follows");
    }
  }
  for (auto& r : dds_->assignments.Take()) {
    const std::string& job_id = r.data.order.job_id;
    const std::string sender = dds_->assignments.WriterParticipant(r.writer);
    if (!r.valid) {
      // Disposed: the coordinator withdrew the job (cancelled, timed out, or its result is in).
      // A coordinator that merely went away (no writers) leaves our jobs running.
      if (r.state == InstanceState::kDisposed && !sender.empty() && sender == coordinator_) {
        changed = changed || running_.count(job_id) > 0;
        Settle(job_id);
        pending_.erase(job_id);
      }
      continue;
    }
    if (!r.decode_error.empty()) {
      dropped_.Drop(sender.empty() ? "an unknown writer" : sender, r.decode_error);
      continue;
    }
    if (r.data.worker_id != options_.id) {
      // Another worker's. If we run it, the job was requeued while we were away and given to
      // that worker: our attempt is stale, stop it.
      if (running_.count(job_id) > 0 && FromCoordinator(sender)) {
        Log(LogLevel::kWarning, job_id + " now belongs to " + r.data.worker_id + "; stopping ours");
        Settle(job_id);
        changed = true;
      }
      continue;
    }
    if (!wire::IsSafePath(job_id, wire::kMaxIdLength) || r.data.order.attempt < 1 ||
        r.data.order.attempt > wire::kMaxAttempt) {
      // Not even a job we could report on: drop it.
      dropped_.Drop(sender.empty() ? "an unknown writer" : sender, "bad job id or attempt");
      continue;
    }
    if (!FromCoordinator(sender)) {
      if (sender.empty() || pending_.size() >= kMaxPending) {
        dropped_.Drop(sender.empty() ? "an unknown writer" : sender,
                      "not the coordinator this worker follows");
      } else {
        pending_[job_id] = {std::move(r.data), sender, now};
      }
      continue;
    }
    Consider(std::move(r.data));
  }
  // A start needs no status (the coordinator counts the jobs it assigned); a job stopped here
  // frees a slot, which it says.
  if (changed)
    PublishStatus();
}

void WorkerDaemon::Consider(msg::JobAssignment a) {
  const auto taken = taken_.find(a.order.job_id);
  if (taken != taken_.end() && taken->second >= a.order.attempt)
    return;  // republished after a coordinator restart, or older than what we run
  Start(std::move(a));
}

void WorkerDaemon::PollJobs() {
  bool changed = false;
  for (auto it = running_.begin(); it != running_.end();) {
    const auto outcome = it->second->Poll();
    if (!outcome) {
      ++it;
      continue;
    }
    msg::JobEvent event;
    event.job_id = it->first;
    event.attempt = it->second->order().attempt;
    event.worker_id = options_.id;
    event.state = outcome->succeeded ? msg::JobState::kSucceeded : msg::JobState::kFailed;
    event.result_json = outcome->result_json;
    event.message = outcome->error.substr(0, wire::kMaxMessage - 1);
    event.provenance = build_;
    event.provenance.scenario_sha256 = it->second->scenario_sha256();
    event.artifacts = outcome->artifacts;
    if (event.result_json.size() > wire::kMaxResultJson) {
      event.state = msg::JobState::kFailed;
      event.result_json.clear();
      event.artifacts.clear();
      event.message =
          "the result is larger than " + std::to_string(wire::kMaxResultJson) + " bytes";
    }
    Log(outcome->succeeded ? LogLevel::kInfo : LogLevel::kWarning,
        it->second->Key() + (outcome->succeeded ? " succeeded" : " failed: " + outcome->error));
    dds_->events.Write(event);
    announced_.insert(it->first);
    progress_sent_.erase(it->first);
    it = running_.erase(it);
    changed = true;
  }
  if (changed)
    PublishStatus();
}

void WorkerDaemon::ReportProgress() {
  for (const auto& [job_id, job] : running_) {
    const std::string line = job->ProgressLine();
    if (line.empty() || progress_sent_[job_id] == line)
      continue;
    progress_sent_[job_id] = line;
    msg::JobEvent event;
    event.job_id = job_id;
    event.attempt = job->order().attempt;
    event.worker_id = options_.id;
    event.state = msg::JobState::kProgress;
    event.message = line.substr(0, wire::kMaxMessage - 1);
    dds_->events.Write(event);
    announced_.insert(job_id);
  }
}

void WorkerDaemon::Run() {
  PublishStatus();
  Log(LogLevel::kInfo,
      "worker " + options_.id + " ready with " + std::to_string(options_.slots) + " slot(s)");
  auto next_progress = std::chrono::steady_clock::now();
  while (!StopRequested()) {
    // Children are polled, not waited for: a short wait keeps job ends prompt.
    dds_->wait_set.Wait(running_.empty() ? 0.2 : 0.05);
    TakeAssignments();
    PollJobs();
    if (std::chrono::steady_clock::now() >= next_progress) {
      ReportProgress();
      next_progress += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(options_.progress_period_s));
    }
  }
  for (auto& [id, job] : running_)
    job->Stop();
  running_.clear();
  msg::WorkerStatus key;
  key.worker_id = options_.id;
  dds_->status.Dispose(key);  // "stopped", not "lost"
}

}  // namespace rlpos
