#include "daemon/coordinator_daemon.h"

#include <chrono>
#include <nlohmann/json.hpp>

#include "campaign/expanded_campaign_json.h"
#include "daemon/scenario_documents.h"
#include "dds/topics.h"
#include "dds/wait_set.h"
#include "logging/log.h"
#include "process/stop_signal.h"
#include "store/store_error.h"

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

CoordinatorDaemon::CoordinatorDaemon(CoordinatorOptions options, const DdsOptions& dds)
    : options_(std::move(options)),
      lock_(options_.db_file + ".coordinator.lock"),
      store_(options_.db_file),
      scheduler_(store_),
      participant_(dds),
      dds_(std::make_unique<Endpoints>(participant_)) {
  // Nothing is known alive until DDS says so.
  store_.MarkAllWorkersLost();
  started_ = Now();
}

CoordinatorDaemon::~CoordinatorDaemon() = default;

double CoordinatorDaemon::Now() const {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

void CoordinatorDaemon::HandleRequests() {
  for (const auto& r : dds_->requests.Take()) {
    if (!r.valid)
      continue;
    msg::CampaignReply reply;
    reply.request_id = r.data.request_id;
    try {
      switch (r.data.kind) {
        case msg::RequestKind::kSubmit: {
          const ExpandedCampaign campaign =
              ExpandedCampaignFromJson(nlohmann::json::parse(r.data.campaign_json));
          const SubmitResult result = store_.Submit(campaign);
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
          const auto stopped = store_.CancelCampaign(r.data.campaign_id);
          for (const auto& job : stopped)
            Withdraw(job.id);
          reply.jobs = static_cast<int>(stopped.size());
          Log(LogLevel::kInfo, "cancelled campaign " + r.data.campaign_id);
          break;
        }
        case msg::RequestKind::kRetry: {
          reply.campaign_id = r.data.campaign_id;
          reply.jobs = store_.RetryFailed(r.data.campaign_id);
          Log(LogLevel::kInfo,
              "retrying " + std::to_string(reply.jobs) + " job(s) of " + r.data.campaign_id);
          break;
        }
      }
      reply.ok = true;
    } catch (const std::exception& e) {
      reply.ok = false;
      reply.message = e.what();
      Log(LogLevel::kWarning, "request " + r.data.request_id + " refused: " + e.what());
    }
    dds_->replies.Write(reply);
  }
}

void CoordinatorDaemon::HandleWorkerStatuses() {
  for (const auto& r : dds_->statuses.Take()) {
    const std::string& id = r.data.worker_id;
    if (r.valid && r.state == InstanceState::kAlive) {
      const bool is_new = live_.count(id) == 0;
      LiveWorker& w = live_[id];
      w.slots = {id, r.data.slots, r.data.busy};
      w.jobs = {r.data.jobs.begin(), r.data.jobs.end()};
      WorkerRecord record;
      record.id = id;
      record.host = r.data.host;
      record.pid = r.data.pid;
      record.slots = r.data.slots;
      record.busy = r.data.busy;
      store_.UpsertWorker(record);
      if (is_new) {
        Log(LogLevel::kInfo,
            "worker " + id + " joined (" + std::to_string(r.data.slots) + " slot(s))");
        // After a restart: a worker that is back gets its running jobs again (it ignores
        // attempts it already has), in case an assignment was lost with the old coordinator.
        for (const auto& job : store_.ListRunning()) {
          if (job.worker_id != id || published_.count(job.id))
            continue;
          if (const auto record_of = store_.GetJob(job.id)) {
            ReadyJob ready;
            ready.id = record_of->id;
            ready.campaign_id = record_of->campaign_id;
            ready.key = record_of->key;
            ready.scenario = record_of->scenario;
            ready.kind = record_of->kind;
            ready.attempt = record_of->attempt;
            ready.timeout_s = job.timeout_s;
            ready.argv = record_of->argv;
            Publish(ready, id);
          }
        }
      }
      continue;
    }
    if (r.valid || r.state == InstanceState::kAlive)
      continue;
    // Disposed: it stopped cleanly; no writers: its lease ran out (killed, or its host is gone).
    const bool stopped = r.state == InstanceState::kDisposed;
    live_.erase(id);
    store_.SetWorkerState(id, stopped ? "stopped" : "lost");
    const auto requeued = scheduler_.WorkerLost(id);
    for (const auto& job_id : requeued)
      published_.erase(job_id);
    Log(LogLevel::kWarning, "worker " + id + (stopped ? " stopped" : " lost") +
                                (requeued.empty() ? ""
                                                  : "; " + std::to_string(requeued.size()) +
                                                        " job(s) back to the queue"));
  }
}

void CoordinatorDaemon::HandleJobEvents() {
  for (const auto& r : dds_->events.Take()) {
    if (!r.valid)
      continue;
    const msg::JobEvent& e = r.data;
    const std::string key = e.job_id + "#" + std::to_string(e.attempt);
    if (e.state == msg::JobState::kStarted || e.state == msg::JobState::kProgress) {
      Log(LogLevel::kDebug, key + " on " + e.worker_id + ": " +
                                (e.message.empty() ? std::string("started") : e.message));
      if (e.state == msg::JobState::kProgress)
        store_.SetProgress(e.job_id, e.attempt, e.message);
      continue;
    }
    JobUpdate update = JobUpdate::kUnknown;
    if (e.state == msg::JobState::kSucceeded) {
      nlohmann::json result;
      try {
        result = nlohmann::json::parse(e.result_json);
      } catch (const nlohmann::json::exception&) {
        update = store_.RecordFailure(e.job_id, e.attempt, "the result is not JSON");
      }
      if (update == JobUpdate::kUnknown)
        update = store_.RecordSuccess(e.job_id, e.attempt, result);
    } else {
      update = store_.RecordFailure(e.job_id, e.attempt, e.message);
    }
    Log(update == JobUpdate::kSucceeded ? LogLevel::kInfo : LogLevel::kWarning,
        key + " from " + e.worker_id + ": " + ToString(update) +
            (e.state == msg::JobState::kFailed ? " (" + e.message + ")" : ""));
    // Settled: the assignment of this attempt goes. A stale event leaves a newer one alone.
    const auto it = published_.find(e.job_id);
    if (it != published_.end() && it->second == e.attempt)
      Withdraw(e.job_id);
  }
}

void CoordinatorDaemon::AfterGrace() {
  grace_over_ = true;
  std::set<std::string> gone;
  for (const auto& job : store_.ListRunning()) {
    if (!live_.count(job.worker_id))
      gone.insert(job.worker_id);
  }
  for (const auto& worker_id : gone) {
    const auto requeued = scheduler_.WorkerLost(worker_id);
    store_.SetWorkerState(worker_id, "lost");
    Log(LogLevel::kWarning, "worker " + worker_id + " did not come back; " +
                                std::to_string(requeued.size()) + " job(s) back to the queue");
  }
}

void CoordinatorDaemon::Publish(const ReadyJob& job, const std::string& worker_id) {
  msg::JobAssignment a;
  a.job_id = job.id;
  a.attempt = job.attempt;
  a.worker_id = worker_id;
  a.campaign_id = job.campaign_id;
  a.argv = job.argv;
  a.scenario_document = ScenarioDocument(job.campaign_id, job.scenario);
  a.timeout_s = job.timeout_s;
  dds_->assignments.Write(a);
  published_[job.id] = job.attempt;
}

void CoordinatorDaemon::Withdraw(const std::string& job_id) {
  msg::JobAssignment key;
  key.job_id = job_id;
  dds_->assignments.Dispose(key);
  published_.erase(job_id);
}

const std::string& CoordinatorDaemon::ScenarioDocument(const std::string& campaign_id,
                                                       const std::string& name) {
  auto it = documents_.find(campaign_id);
  if (it == documents_.end()) {
    const auto spec = store_.CampaignSpecJson(campaign_id);
    it = documents_
             .emplace(campaign_id,
                      spec ? ScenarioDocumentsByName(*spec) : std::map<std::string, std::string>{})
             .first;
  }
  static const std::string kNone;
  const auto doc = it->second.find(name);
  return doc == it->second.end() ? kNone : doc->second;
}

void CoordinatorDaemon::Schedule() {
  std::vector<WorkerSlots> workers;
  for (const auto& [id, w] : live_)
    workers.push_back(w.slots);
  const TickResult tick = scheduler_.Tick(workers, Now());
  for (const auto& t : tick.timed_out) {
    Log(LogLevel::kWarning,
        t.job.id + "#" + std::to_string(t.job.attempt) + " on " + t.job.worker_id + ": " + t.error);
    Withdraw(t.job.id);
  }
  for (const auto& a : tick.assigned) {
    Publish(a.job, a.worker_id);
    if (auto it = live_.find(a.worker_id); it != live_.end())
      ++it->second.slots.busy;
    Log(LogLevel::kDebug,
        "assigned " + a.job.id + "#" + std::to_string(a.job.attempt) + " to " + a.worker_id);
  }
}

void CoordinatorDaemon::Run() {
  Log(LogLevel::kInfo, "coordinator ready on DDS domain " +
                           std::to_string(participant_.options().domain) + ", database " +
                           store_.file());
  while (!StopRequested()) {
    dds_->wait_set.Wait(options_.tick_s);
    HandleRequests();
    HandleWorkerStatuses();
    HandleJobEvents();
    if (!grace_over_ && Now() - started_ >= options_.restart_grace_s)
      AfterGrace();
    Schedule();
  }
  Log(LogLevel::kInfo, "coordinator stopping");
}

}  // namespace rlpos
