#include "daemon/worker_daemon.h"

#include <unistd.h>

#include <chrono>

#include "dds/topics.h"
#include "dds/wait_set.h"
#include "logging/log.h"
#include "process/host_name.h"
#include "process/stop_signal.h"

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
      participant_(dds),
      dds_(std::make_unique<Endpoints>(participant_)) {}

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

void WorkerDaemon::TakeAssignments() {
  bool changed = false;
  for (const auto& r : dds_->assignments.Take()) {
    const std::string& job_id = r.data.job_id;
    if (!r.valid) {
      // Disposed: the coordinator withdrew the job (cancelled, timed out, or its result is in).
      // A coordinator that merely went away (no writers) leaves our jobs running.
      if (r.state != InstanceState::kDisposed)
        continue;
      const auto it = running_.find(job_id);
      if (it == running_.end())
        continue;
      Log(LogLevel::kInfo, "stopping " + it->second->Key() + " (withdrawn by the coordinator)");
      it->second->Stop();
      running_.erase(it);
      progress_sent_.erase(job_id);
      changed = true;
      continue;
    }
    if (r.data.worker_id != options_.id)
      continue;
    const std::string key = job_id + "#" + std::to_string(r.data.attempt);
    if (!seen_.insert(key).second)
      continue;  // republished after a coordinator restart
    if (const auto it = running_.find(job_id); it != running_.end()) {
      // A newer attempt of a job we still run: the old one is out of date.
      it->second->Stop();
      running_.erase(it);
    }
    JobAttemptSpec spec{job_id, r.data.attempt, r.data.argv, r.data.scenario_document,
                        r.data.timeout_s};
    msg::JobEvent event;
    event.job_id = job_id;
    event.attempt = r.data.attempt;
    event.worker_id = options_.id;
    try {
      running_[job_id] = std::make_unique<JobAttempt>(spec, options_.work_dir, options_.sim_binary);
      event.state = msg::JobState::kStarted;
      Log(LogLevel::kInfo, "started " + key);
    } catch (const std::exception& e) {
      event.state = msg::JobState::kFailed;
      event.message = std::string("worker could not start the job: ") + e.what();
      Log(LogLevel::kWarning, key + ": " + event.message);
    }
    dds_->events.Write(event);
    changed = true;
  }
  if (changed)
    PublishStatus();
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
    event.attempt = it->second->spec().attempt;
    event.worker_id = options_.id;
    event.state = outcome->succeeded ? msg::JobState::kSucceeded : msg::JobState::kFailed;
    event.result_json = outcome->result_json;
    event.message = outcome->error;
    Log(outcome->succeeded ? LogLevel::kInfo : LogLevel::kWarning,
        it->second->Key() + (outcome->succeeded ? " succeeded" : " failed: " + outcome->error));
    dds_->events.Write(event);
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
    event.attempt = job->spec().attempt;
    event.worker_id = options_.id;
    event.state = msg::JobState::kProgress;
    event.message = line;
    dds_->events.Write(event);
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
