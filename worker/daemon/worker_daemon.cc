#include "worker/daemon/worker_daemon.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>

#include "common/logging/log.h"
#include "common/process/host_name.h"
#include "common/process/stop_signal.h"
#include "common/wire/identifiers.h"
#include "common/wire/limits.h"
#include "idl/dds/topics.h"
#include "idl/dds/wait_set.h"

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
      dds_(std::make_unique<Endpoints>(participant_)),
      slots_(static_cast<std::size_t>(options_.slots)) {
  build_.host = HostName();
}

WorkerDaemon::~WorkerDaemon() = default;

void WorkerDaemon::PublishStatus() {
  msg::WorkerStatus status;
  status.worker_id = options_.id;
  status.host = HostName();
  status.pid = getpid();
  status.slots = options_.slots;
  for (const auto& slot : slots_) {
    if (slot.run)
      status.jobs.push_back(slot.run->Key());
  }
  status.busy = static_cast<int>(status.jobs.size());
  dds_->status.Write(status);
}

msg::JobEvent WorkerDaemon::EventOf(int slot) const {
  msg::JobEvent event;
  event.worker_id = options_.id;
  event.slot = slot;
  event.job_id = slots_[slot].job_id;
  event.attempt = slots_[slot].attempt;
  return event;
}

void WorkerDaemon::Empty(int slot, const std::string& why) {
  Slot& s = slots_[slot];
  if (s.run) {
    Log(LogLevel::kInfo, "stopping " + s.run->Key() + " (" + why + ")");
    s.run->Stop();
  }
  if (s.announced)
    dds_->events.Dispose(EventOf(slot));
  s = Slot{};
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

void WorkerDaemon::Start(int slot, msg::JobAssignment a) {
  Slot& s = slots_[slot];
  s.job_id = a.order.job_id;
  s.attempt = a.order.attempt;
  const std::string key = s.job_id + "#" + std::to_string(s.attempt);
  try {
    // Checked before anything is written: a bad order leaves no trace but the event.
    CheckedOrder checked;
    try {
      checked = CheckJobOrder(a.order, options_.max_timeout_s);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("invalid job: ") + e.what());
    }
    s.run = std::make_unique<JobAttempt>(std::move(a.order), checked.scenario, options_.work_dir,
                                         options_.sim_binary);
    // No event for a start: the coordinator marked the job running when it assigned it, and
    // one sample fewer per job is the coordinator's time.
    Log(LogLevel::kInfo, "started " + key + " in slot " + std::to_string(slot));
  } catch (const std::exception& e) {
    msg::JobEvent event = EventOf(slot);
    event.state = msg::JobState::kFailed;
    event.message = std::string("worker could not start the job: ") + e.what();
    event.message = event.message.substr(0, wire::kMaxMessage - 1);
    Log(LogLevel::kWarning, key + ": " + event.message);
    // The slot keeps the refused attempt until the coordinator empties it.
    dds_->events.Write(event);
    s.announced = true;
  }
}

void WorkerDaemon::TakeAssignments() {
  bool changed = false;
  // Assignments from a coordinator this worker does not follow (yet) wait: after a coordinator
  // restart the new one can publish before the old one's writer is gone (its lease), and its
  // jobs must not be lost. They run once it is the one followed, or go after a while.
  const auto now = std::chrono::steady_clock::now();
  std::map<int, PendingAssignment> waiting;
  waiting.swap(pending_);
  for (auto& [slot, p] : waiting) {
    if (FromCoordinator(p.sender)) {
      changed = Consider(std::move(p.assignment)) || changed;
    } else if (now - p.since < kPendingFor) {
      pending_.emplace(slot, std::move(p));
    } else {
      dropped_.Drop(p.sender, "not the coordinator this worker follows");
    }
  }
  for (auto& r : dds_->assignments.Take()) {
    const std::string sender = dds_->assignments.WriterParticipant(r.writer);
    const bool mine = r.data.worker_id == options_.id;
    const int slot = r.data.slot;
    if (mine && (slot < 0 || slot >= options_.slots)) {
      dropped_.Drop(sender.empty() ? "an unknown writer" : sender,
                    "slot " + std::to_string(slot) + " is not one of this worker's " +
                        std::to_string(options_.slots));
      continue;
    }
    if (!r.valid) {
      // Disposed: the coordinator emptied the slot (cancelled, timed out, or its result is in).
      // A coordinator that merely went away (no writers) leaves our jobs running.
      if (mine && r.state == InstanceState::kDisposed && !sender.empty() &&
          sender == coordinator_) {
        changed = changed || slots_[slot].run != nullptr;
        Empty(slot, "withdrawn by the coordinator");
        pending_.erase(slot);
      }
      continue;
    }
    if (!r.decode_error.empty()) {
      dropped_.Drop(sender.empty() ? "an unknown writer" : sender, r.decode_error);
      continue;
    }
    const std::string& job_id = r.data.order.job_id;
    if (!mine) {
      // Another worker's. If we hold it, the job was requeued while we were away and given to
      // that worker: our attempt is stale, stop it.
      for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (slots_[i].job_id == job_id && FromCoordinator(sender)) {
          Empty(static_cast<int>(i), "now " + r.data.worker_id + "'s");
          changed = true;
        }
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
      if (sender.empty()) {
        dropped_.Drop("an unknown writer", "not the coordinator this worker follows");
      } else {
        pending_[slot] = {std::move(r.data), sender, now};
      }
      continue;
    }
    pending_.erase(slot);
    changed = Consider(std::move(r.data)) || changed;
  }
  // A start needs no status (the coordinator counts the jobs it assigned); a job stopped here
  // frees a slot, which it says.
  if (changed)
    PublishStatus();
}

bool WorkerDaemon::Consider(msg::JobAssignment a) {
  const int slot = a.slot;
  Slot& s = slots_[slot];
  if (s.job_id == a.order.job_id && s.attempt >= a.order.attempt)
    return false;  // republished after a coordinator restart, or older than the slot's
  bool stopped = false;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    // The slot's job, or an older attempt of this job in another slot: out of date.
    if (static_cast<int>(i) == slot ? !s.job_id.empty() : slots_[i].job_id == a.order.job_id) {
      stopped = stopped || slots_[i].run != nullptr;
      Empty(static_cast<int>(i), "its slot was given " + a.order.job_id);
    }
  }
  Start(slot, std::move(a));
  return stopped;
}

void WorkerDaemon::PollJobs() {
  bool changed = false;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Slot& s = slots_[i];
    if (!s.run)
      continue;
    const auto outcome = s.run->Poll();
    if (!outcome)
      continue;
    msg::JobEvent event = EventOf(static_cast<int>(i));
    event.state = outcome->succeeded ? msg::JobState::kSucceeded : msg::JobState::kFailed;
    event.result_json = outcome->result_json;
    event.message = outcome->error.substr(0, wire::kMaxMessage - 1);
    event.provenance = build_;
    event.provenance.scenario_sha256 = s.run->scenario_sha256();
    event.artifacts = outcome->artifacts;
    if (event.result_json.size() > wire::kMaxResultJson) {
      event.state = msg::JobState::kFailed;
      event.result_json.clear();
      event.artifacts.clear();
      event.message =
          "the result is larger than " + std::to_string(wire::kMaxResultJson) + " bytes";
    }
    Log(outcome->succeeded ? LogLevel::kInfo : LogLevel::kWarning,
        s.run->Key() + (outcome->succeeded ? " succeeded" : " failed: " + outcome->error));
    dds_->events.Write(event);
    s.announced = true;
    s.progress_sent.clear();
    s.run.reset();  // the slot holds the attempt until the coordinator empties it
    changed = true;
  }
  if (changed)
    PublishStatus();
}

void WorkerDaemon::ReportProgress() {
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Slot& s = slots_[i];
    if (!s.run)
      continue;
    const std::string line = s.run->ProgressLine();
    if (line.empty() || s.progress_sent == line)
      continue;
    s.progress_sent = line;
    msg::JobEvent event = EventOf(static_cast<int>(i));
    event.state = msg::JobState::kProgress;
    event.message = line.substr(0, wire::kMaxMessage - 1);
    dds_->events.Write(event);
    s.announced = true;
  }
}

void WorkerDaemon::Run() {
  PublishStatus();
  Log(LogLevel::kInfo,
      "worker " + options_.id + " ready with " + std::to_string(options_.slots) + " slot(s)");
  auto next_progress = std::chrono::steady_clock::now();
  while (!StopRequested()) {
    // Children are polled, not waited for: a short wait keeps job ends prompt.
    const bool busy =
        std::any_of(slots_.begin(), slots_.end(), [](const Slot& s) { return !!s.run; });
    dds_->wait_set.Wait(busy ? 0.05 : 0.2);
    TakeAssignments();
    PollJobs();
    if (std::chrono::steady_clock::now() >= next_progress) {
      ReportProgress();
      next_progress += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(options_.progress_period_s));
    }
  }
  for (auto& slot : slots_) {
    if (slot.run)
      slot.run->Stop();
  }
  slots_.clear();
  msg::WorkerStatus key;
  key.worker_id = options_.id;
  dds_->status.Dispose(key);  // "stopped", not "lost"
}

}  // namespace rlpos
