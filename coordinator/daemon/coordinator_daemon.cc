#include "coordinator/daemon/coordinator_daemon.h"

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "common/logging/log.h"
#include "common/process/stop_signal.h"
#include "common/process/wall_clock.h"
#include "common/store/artifact_files.h"
#include "common/store/store_error.h"
#include "common/wire/json_text.h"
#include "common/wire/limits.h"
#include "common/wire/policy_bundle_files.h"
#include "coordinator/daemon/scenario_documents.h"
#include "idl/dds/message_checks.h"
#include "idl/dds/topics.h"
#include "idl/dds/wait_set.h"

namespace rlpos {

struct CoordinatorDaemon::Endpoints {
  explicit Endpoints(Participant& p)
      : requests(p), replies(p), statuses(p), assignments(p), events(p), wait_set(p) {
    wait_set.Attach(requests.handle());
    wait_set.Attach(statuses.handle());
    wait_set.Attach(events.handle());
  }
  Reader<msg::CampaignRequest> requests;
  Writer<msg::CampaignReply> replies;
  Reader<msg::WorkerStatus> statuses;
  Writer<msg::JobAssignment> assignments;
  Reader<msg::JobEvent> events;
  WaitSet wait_set;
};

namespace {

// What a deferred event holds in memory, about.
std::size_t EventBytes(const msg::JobEvent& e) {
  std::size_t bytes = sizeof e + e.result_json.size() + e.message.size();
  for (const auto& a : e.artifacts)
    bytes += a.data.size();
  return bytes;
}

// The key of a worker slot's assignment instance (the other fields are ignored).
msg::JobAssignment SlotKey(const std::string& worker_id, int slot) {
  msg::JobAssignment key;
  key.worker_id = worker_id;
  key.slot = slot;
  return key;
}

StoreOptions StoreOptionsOf(const CoordinatorOptions& options) {
  StoreOptions store;
  store.max_infra_losses = options.max_infra_losses;
  return store;
}

}  // namespace

CoordinatorDaemon::CoordinatorDaemon(CoordinatorOptions options, const DdsOptions& dds)
    : options_(std::move(options)),
      lock_(options_.db_file + ".coordinator.lock"),
      store_(options_.db_file, StoreOptionsOf(options_)),
      scheduler_(store_.ledger),
      participant_(dds),
      dds_(std::make_unique<Endpoints>(participant_)) {
  // Nothing is known alive until DDS says so.
  store_.ledger.MarkAllWorkersLost();
  started_ = Now();
}

CoordinatorDaemon::~CoordinatorDaemon() = default;

double CoordinatorDaemon::Now() const {
  return WallClockSeconds();
}

void CoordinatorDaemon::HandleRequests() {
  for (auto& r : dds_->requests.Take()) {
    if (!r.valid)
      continue;
    const std::string sender = dds_->requests.WriterParticipant(r.writer);
    std::string problem = r.decode_error.empty() ? CheckCampaignRequest(r.data) : r.decode_error;
    if (!problem.empty()) {
      dropped_requests_.Drop(sender.empty() ? "an unknown writer" : sender, problem);
      continue;
    }
    msg::CampaignReply reply;
    reply.request_id = r.data.request_id;
    try {
      switch (r.data.kind) {
        case msg::RequestKind::kSubmit: {
          CampaignPlan campaign = PlanSubmittedCampaign(r.data.campaign_json, r.data.scenarios,
                                                        r.data.policies, options_.limits);
          campaign.use_cache = !r.data.no_cache;
          // Kept by hash before any job names it: a job's policy is always there to send.
          for (const auto& policy : campaign.parsed.policies)
            WritePolicyBundle(policy.bundle, PoliciesDirOf(options_.db_file));
          const SubmitResult result = store_.ledger.Submit(campaign);
          reply.campaign_id = result.campaign_id;
          reply.jobs = result.jobs;
          reply.created = result.created;
          Log(LogLevel::kInfo, std::string(result.created ? "accepted" : "already have") +
                                   " campaign " + campaign.name + " (" + result.campaign_id + ", " +
                                   std::to_string(result.jobs) + " jobs)");
          break;
        }
        case msg::RequestKind::kCancel: {
          reply.campaign_id = r.data.campaign_id;
          const auto stopped = store_.ledger.CancelCampaign(r.data.campaign_id);
          for (const auto& job : stopped)
            Withdraw(job.id);
          reply.jobs = static_cast<int>(stopped.size());
          Log(LogLevel::kInfo, "cancelled campaign " + r.data.campaign_id);
          break;
        }
        case msg::RequestKind::kRetry: {
          reply.campaign_id = r.data.campaign_id;
          reply.jobs = store_.ledger.RetryFailed(r.data.campaign_id);
          Log(LogLevel::kInfo,
              "retrying " + std::to_string(reply.jobs) + " job(s) of " + r.data.campaign_id);
          break;
        }
      }
      reply.ok = true;
    } catch (const std::exception& e) {
      reply = msg::CampaignReply{};
      reply.request_id = r.data.request_id;
      reply.ok = false;
      reply.message = std::string(e.what()).substr(0, wire::kMaxMessage - 1);
      refused_requests_.Drop(sender.empty() ? "an unknown writer" : sender,
                             "request " + r.data.request_id + " refused: " + reply.message);
    }
    // Volatile: the client is matched before it asks. Unregistered at once: nothing is kept
    // per request.
    dds_->replies.Write(reply);
    dds_->replies.Unregister(reply);
  }
}

void CoordinatorDaemon::HandleWorkerStatuses() {
  for (const auto& r : dds_->statuses.Take()) {
    const std::string& id = r.data.worker_id;
    const std::string sender = dds_->statuses.WriterParticipant(r.writer);
    const auto known = live_.find(id);
    if (r.valid) {
      std::string problem = r.decode_error.empty() ? CheckWorkerStatus(r.data) : r.decode_error;
      if (problem.empty() && known != live_.end() && known->second.participant != sender)
        problem = "worker id " + id + " belongs to another participant";
      if (problem.empty() && sender.empty())
        problem = "its writer is not matched";
      if (!problem.empty()) {
        dropped_statuses_.Drop(sender.empty() ? "an unknown writer" : sender, problem);
        continue;
      }
      const bool is_new = known == live_.end();
      LiveWorker& w = live_[id];
      w.participant = sender;
      w.slots = {id, r.data.slots, r.data.busy};
      w.jobs = {r.data.jobs.begin(), r.data.jobs.end()};
      // The workers table is for `status`: a busy count a second old is news enough, and a
      // write per status (two per job) is not free.
      const double now = Now();
      if (is_new || w.host != r.data.host || w.pid != r.data.pid ||
          now - w.written_at >= kWorkerRowPeriodS) {
        WorkerRecord record;
        record.id = id;
        record.host = r.data.host;
        record.pid = r.data.pid;
        record.slots = r.data.slots;
        record.busy = r.data.busy;
        store_.ledger.UpsertWorker(record);
        w.host = r.data.host;
        w.pid = r.data.pid;
        w.written_at = now;
      }
      if (is_new) {
        Log(LogLevel::kInfo,
            "worker " + id + " joined (" + std::to_string(r.data.slots) + " slot(s))");
        WithdrawStale(id, r.data.slots, r.data.jobs);
        Republish(id);
      }
      continue;
    }
    if (known == live_.end() || r.state == InstanceState::kAlive)
      continue;
    // Disposed: it stopped cleanly, which only its own participant may say; no writers: its
    // lease ran out (killed, or its host is gone), which Cyclone decides locally.
    const bool stopped = r.state == InstanceState::kDisposed;
    if (stopped && sender != known->second.participant) {
      dropped_statuses_.Drop(sender.empty() ? "an unknown writer" : sender,
                             "dispose of worker " + id + "'s status by another participant");
      continue;
    }
    const int slots = known->second.slots.slots;
    live_.erase(known);
    store_.ledger.SetWorkerState(id, stopped ? "stopped" : "lost");
    const auto requeued = scheduler_.WorkerLost(id);
    for (const auto& job_id : requeued)
      Withdraw(job_id);
    if (stopped) {
      // Gone for good: its slots' instances go too (a lost worker may come back to them).
      for (int slot = 0; slot < slots; ++slot)
        dds_->assignments.Unregister(SlotKey(id, slot));
    }
    Log(LogLevel::kWarning, "worker " + id + (stopped ? " stopped" : " lost") +
                                (requeued.empty() ? ""
                                                  : "; " + std::to_string(requeued.size()) +
                                                        " job(s) back to the queue"));
  }
}

std::size_t CoordinatorDaemon::HandleJobEvents() {
  // Events whose worker had not announced itself yet: a worker's status and its events travel
  // on different topics, so after a coordinator restart (or a worker's return) an event can come
  // first. They wait here a while, bounded, instead of being lost.
  const double now = Now();
  std::vector<DeferredEvent> waiting;
  waiting.swap(deferred_events_);
  deferred_bytes_ = 0;
  for (auto& d : waiting) {
    if (live_.count(d.event.worker_id) > 0) {
      HandleJobEvent(d.event, d.sender);
    } else if (now - d.since < kEventDeferralS) {
      deferred_bytes_ += EventBytes(d.event);
      deferred_events_.push_back(std::move(d));
    } else {
      dropped_events_.Drop(d.sender, "worker " + d.event.worker_id + " is not live");
    }
  }
  const auto samples = dds_->events.Take();
  for (const auto& r : samples) {
    if (!r.valid)
      continue;
    const std::string sender = dds_->events.WriterParticipant(r.writer);
    std::string problem = r.decode_error.empty() ? CheckJobEvent(r.data) : r.decode_error;
    if (!problem.empty()) {
      dropped_events_.Drop(sender.empty() ? "an unknown writer" : sender, problem);
      continue;
    }
    if (live_.count(r.data.worker_id) == 0 && !sender.empty() &&
        deferred_events_.size() < kMaxDeferredEvents &&
        deferred_bytes_ + EventBytes(r.data) <= kMaxDeferredBytes) {
      deferred_bytes_ += EventBytes(r.data);
      deferred_events_.push_back({r.data, sender, now});
      continue;
    }
    HandleJobEvent(r.data, sender);
  }
  return samples.size();
}

void CoordinatorDaemon::HandleJobEvent(const msg::JobEvent& e, const std::string& sender) {
  // Only the participant that announced the worker speaks for it.
  std::string problem;
  const auto w = live_.find(e.worker_id);
  if (w == live_.end())
    problem = "worker " + e.worker_id + " is not live";
  else if (sender.empty() || w->second.participant != sender)
    problem = "not written by worker " + e.worker_id + "'s participant";
  if (!problem.empty()) {
    dropped_events_.Drop(sender.empty() ? "an unknown writer" : sender, problem);
    return;
  }
  const std::string key = e.job_id + "#" + std::to_string(e.attempt);
  if (e.state == msg::JobState::kStarted || e.state == msg::JobState::kProgress) {
    Log(LogLevel::kDebug, key + " on " + e.worker_id + ": " +
                              (e.message.empty() ? std::string("started") : e.message));
    if (e.state == msg::JobState::kProgress)
      store_.ledger.SetProgress(e.job_id, e.attempt, e.message, e.worker_id);
    return;
  }
  JobUpdate update = JobUpdate::kUnknown;
  if (e.state == msg::JobState::kSucceeded) {
    nlohmann::json result;
    try {
      result = wire::ParseBoundedJson(e.result_json, wire::kMaxResultJson, "the result");
    } catch (const std::invalid_argument& error) {
      update = store_.ledger.RecordFailure(e.job_id, e.attempt, error.what(), e.worker_id);
    }
    if (update == JobUpdate::kUnknown)
      update = store_.recorder.RecordSuccess(e.job_id, e.attempt, result, e.worker_id,
                                             &e.provenance, e.artifacts);
  } else {
    update = store_.ledger.RecordFailure(e.job_id, e.attempt, e.message, e.worker_id);
  }
  if (update == JobUpdate::kUnknown || update == JobUpdate::kStale) {
    // Not the worker's current attempt (late, duplicate, or not its job): nothing changed.
    dropped_events_.Drop(sender, key + " from " + e.worker_id + " is " + ToString(update));
    return;
  }
  Log(update == JobUpdate::kSucceeded ? LogLevel::kInfo : LogLevel::kWarning,
      key + " from " + e.worker_id + ": " + ToString(update) +
          (e.state == msg::JobState::kFailed ? " (" + e.message + ")" : ""));
  // Settled: the assignment of this attempt goes.
  const auto it = published_.find(e.job_id);
  if (it != published_.end() && it->second.attempt == e.attempt)
    Withdraw(e.job_id);
}

void CoordinatorDaemon::WithdrawStale(const std::string& worker_id, int slots,
                                      const std::vector<std::string>& jobs) {
  // A worker back after its lease ran out may still run jobs that went back to the queue (and
  // maybe to another worker) meanwhile: their results would be stale, so empty their slots.
  // Which slot the worker put a stale job in is its own business: every slot that the store
  // does not give a job of this worker is emptied.
  std::set<std::string> held;
  std::set<int> held_slots;
  for (const auto& job : store_.ledger.ListRunning()) {
    if (job.worker_id == worker_id) {
      held.insert(job.id + "#" + std::to_string(job.attempt));
      held_slots.insert(job.slot);
    }
  }
  bool stale = false;
  for (const auto& key : jobs) {
    if (held.count(key))
      continue;
    Log(LogLevel::kWarning, "worker " + worker_id + " came back with " + key +
                                ", which is no longer its job; stopping it there");
    stale = true;
  }
  if (!stale)
    return;
  for (int slot = 0; slot < slots; ++slot) {
    if (!held_slots.count(slot))
      DisposeSlot(worker_id, slot);
  }
}

void CoordinatorDaemon::AfterGrace() {
  grace_over_ = true;
  std::set<std::string> gone;
  for (const auto& job : store_.ledger.ListRunning()) {
    if (!live_.count(job.worker_id))
      gone.insert(job.worker_id);
  }
  for (const auto& worker_id : gone) {
    const auto requeued = scheduler_.WorkerLost(worker_id);
    for (const auto& job_id : requeued)
      Withdraw(job_id);
    store_.ledger.SetWorkerState(worker_id, "lost");
    Log(LogLevel::kWarning, "worker " + worker_id + " did not come back; " +
                                std::to_string(requeued.size()) + " job(s) back to the queue");
  }
}

void CoordinatorDaemon::Publish(const ReadyJob& job, const std::string& worker_id, int slot) {
  msg::JobAssignment a;
  a.worker_id = worker_id;
  a.slot = slot;
  a.order.job_id = job.id;
  a.order.campaign_id = job.campaign_id;
  a.order.attempt = job.attempt;
  a.order.timeout_s = job.timeout_s;
  a.order.params = job.params;
  a.order.placement = job.placement;
  a.order.scenario_document = ScenarioDocument(job.campaign_id, job.params.scenario);
  if (!job.params.policy_sha256.empty())
    a.order.policy = Policy(job.params.policy_sha256);
  dds_->assignments.Write(a);
  published_[job.id] = {job.attempt, worker_id, slot};
}

void CoordinatorDaemon::Republish(const std::string& worker_id) {
  // After a restart: a worker that is back gets its running jobs again (it ignores attempts it
  // already has), in case an assignment was lost with the old coordinator.
  for (const auto& job : store_.ledger.ListRunning()) {
    if (job.worker_id != worker_id || published_.count(job.id))
      continue;
    if (const auto record = store_.reader.GetJob(job.id)) {
      ReadyJob ready;
      ready.id = record->id;
      ready.campaign_id = record->campaign_id;
      ready.key = record->key;
      ready.attempt = record->attempt;
      ready.timeout_s = record->timeout_s;
      ready.params = record->params;
      ready.placement = record->placement;
      Publish(ready, worker_id, record->slot);
    }
  }
}

void CoordinatorDaemon::Withdraw(const std::string& job_id) {
  // A job this coordinator did not publish is on a worker that has not come back since a
  // restart: WithdrawStale empties its slot when it does.
  const auto it = published_.find(job_id);
  if (it == published_.end())
    return;
  DisposeSlot(it->second.worker_id, it->second.slot);
  published_.erase(it);
}

void CoordinatorDaemon::DisposeSlot(const std::string& worker_id, int slot) {
  // Disposed, never unregistered: the slot's instance is used again by its next job, and a
  // worker that comes back after a partition still learns that the slot was emptied.
  dds_->assignments.Dispose(SlotKey(worker_id, slot));
}

const std::string& CoordinatorDaemon::ScenarioDocument(const std::string& campaign_id,
                                                       const std::string& name) {
  auto it = documents_.find(campaign_id);
  if (it == documents_.end()) {
    const auto spec = store_.reader.CampaignSpecPart(campaign_id, "scenarios");
    it = documents_
             .emplace(campaign_id,
                      spec ? ScenarioDocumentsByName(*spec) : std::map<std::string, std::string>{})
             .first;
  }
  static const std::string kNone;
  const auto doc = it->second.find(name);
  return doc == it->second.end() ? kNone : doc->second;
}

std::optional<PolicyBundle> CoordinatorDaemon::Policy(const std::string& sha256) {
  auto it = policies_.find(sha256);
  if (it == policies_.end()) {
    try {
      it =
          policies_.emplace(sha256, ReadStoredPolicyBundle(PoliciesDirOf(options_.db_file), sha256))
              .first;
    } catch (const std::exception& e) {
      // Sent without it, the job fails on the worker ("policy: the job's is missing").
      Log(LogLevel::kWarning, e.what());
      return std::nullopt;
    }
  }
  return it->second;
}

TickResult CoordinatorDaemon::Schedule() {
  std::vector<WorkerSlots> workers;
  for (const auto& [id, w] : live_)
    workers.push_back(w.slots);
  return scheduler_.Tick(workers, Now());
}

void CoordinatorDaemon::PublishTick(const TickResult& tick) {
  for (const auto& t : tick.timed_out) {
    Log(LogLevel::kWarning,
        t.job.id + "#" + std::to_string(t.job.attempt) + " on " + t.job.worker_id + ": " + t.error);
    Withdraw(t.job.id);
  }
  for (const auto& a : tick.assigned) {
    // No optimistic busy count here: the store's running jobs count for the next round, and a
    // job that never reached its worker (and times out) must not hold its slot for ever.
    Publish(a.job, a.worker_id, a.slot);
    Log(LogLevel::kDebug, "assigned " + a.job.id + "#" + std::to_string(a.job.attempt) + " to " +
                              a.worker_id + " slot " + std::to_string(a.slot));
  }
}

void CoordinatorDaemon::Run() {
  Log(LogLevel::kInfo, "coordinator ready on DDS domain " +
                           std::to_string(participant_.options().domain) + ", database " +
                           store_.db.file());
  auto last_round = std::chrono::steady_clock::now();
  bool busy = false;
  while (!StopRequested()) {
    dds_->wait_set.Wait(options_.tick_s);
    // While jobs come and go, rounds are at least kMinRound apart: at hundreds of samples a
    // second each round then takes many events and one commit, instead of one commit per
    // sample. A quiet coordinator answers at once.
    const auto since = std::chrono::steady_clock::now() - last_round;
    if (busy && since < kMinRound)
      std::this_thread::sleep_for(kMinRound - since);
    last_round = std::chrono::steady_clock::now();
    HandleRequests();  // its replies follow its own commits
    // One commit for the round's statuses, events and assignments; the assignments go out
    // only once it is on disk, so a restarted coordinator never forgets a job it handed out.
    StoreBatch batch = store_.db.Batch();
    HandleWorkerStatuses();
    const std::size_t events = HandleJobEvents();
    if (!grace_over_ && Now() - started_ >= options_.restart_grace_s)
      AfterGrace();
    const TickResult tick = Schedule();
    batch.Commit();
    PublishTick(tick);
    busy = events > 0 || !tick.assigned.empty();
  }
  Log(LogLevel::kInfo, "coordinator stopping");
}

}  // namespace rlpos
