#include "common/store/job_ledger.h"

#include <nlohmann/json.hpp>

#include "common/campaign/job_content.h"
#include "common/store/job_rows.h"
#include "common/store/result_cache.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

std::string OverridesJson(const std::vector<ScenarioOverride>& overrides) {
  json out = json::array();
  for (const auto& o : overrides)
    out.push_back({o.path, o.value});
  return out.dump();
}

}  // namespace

const char* ToString(JobUpdate update) {
  switch (update) {
    case JobUpdate::kSucceeded:
      return "succeeded";
    case JobUpdate::kRetrying:
      return "retrying";
    case JobUpdate::kFailed:
      return "failed";
    case JobUpdate::kStale:
      return "stale";
    case JobUpdate::kUnknown:
      return "unknown";
  }
  return "?";
}

JobLedger::JobLedger(StoreDb& store, ResultCache& cache)
    : store_(store), db_(&store.sql()), cache_(cache) {}

SubmitResult JobLedger::Submit(const CampaignPlan& campaign) {
  Transaction transaction(*db_);
  SubmitResult result{campaign.id, false, 0};
  const std::string& spec_text = campaign.spec_json;
  Statement existing = db_->Prepare("SELECT spec_json FROM campaigns WHERE id = ?");
  existing.Bind(campaign.id);
  if (existing.Step()) {
    if (existing.Text(existing.Column("spec_json")) != spec_text) {
      // 48 bits of FNV-1a make this practically impossible; refuse rather than mix campaigns.
      throw StoreError(store_.file(),
                       "campaign id " + campaign.id + " is taken by another campaign");
    }
    Statement count = db_->Prepare("SELECT COUNT(*) AS jobs FROM jobs WHERE campaign_id = ?");
    count.Bind(campaign.id).Step();
    result.jobs = static_cast<int>(count.Int(count.Column("jobs")));
    return result;  // the transaction rolls back: nothing was written
  }

  const double now = store_.Now();
  db_->Prepare(
         "INSERT INTO campaigns (id, name, spec_json, created_at, state, max_attempts, "
         "job_timeout_s, use_cache) VALUES (?, ?, ?, ?, 'active', ?, ?, ?)")
      .Bind(campaign.id)
      .Bind(campaign.name)
      .Bind(spec_text)
      .Bind(now)
      .Bind(campaign.max_attempts)
      .Bind(campaign.job_timeout_s)
      .Bind(campaign.use_cache ? 1 : 0)
      .Run();
  std::vector<std::string> cacheable;  // ready jobs whose content is known
  int seq = 0;
  InsertJobs(campaign, now, seq, cacheable);
  if (campaign.use_cache) {
    for (const auto& id : cacheable)
      cache_.ResolveFromCache(id);
  }
  UpdateCampaignState(campaign.id);
  transaction.Commit();
  result.created = true;
  result.jobs = seq;
  return result;
}

void JobLedger::InsertJobs(const CampaignPlan& campaign, double now, int& seq,
                           std::vector<std::string>& cacheable) {
  Statement insert = db_->Prepare(
      "INSERT INTO jobs (id, campaign_id, seq, kind, key, scenario, label, rng_run, train_seed, "
      "fidelity, train_episodes, positioner, duration_s, warmup_s, overrides_json, "
      "depends_on, state, attempt, max_attempts, timeout_s, created_at, "
      "position_rule_json, content_base, cache_key, policy_sha256) VALUES (?, ?, ?, ?, ?, ?, ?, "
      "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, 1, ?, ?, ?, ?, ?, ?, ?)");
  const auto text_or_null = [](const std::string& text) {
    return text.empty() ? std::nullopt : std::optional<std::string>(text);
  };
  campaign.ForEachJob([&](Job&& job) {
    const JobParams& p = job.params;
    insert.Reset();
    insert.Bind(job.id)
        .Bind(campaign.id)
        .Bind(seq++)
        .Bind(ToString(p.kind))
        .Bind(job.key)
        .Bind(p.scenario)
        .Bind(job.label)
        .Bind(p.rng_run)
        .Bind(p.train_seed)
        .Bind(text_or_null(p.fidelity))
        .Bind(p.train_episodes)
        .Bind(text_or_null(p.positioner))
        .Bind(p.duration_s)
        .Bind(p.warmup_s)
        .Bind(OverridesJson(p.overrides));
    if (job.depends_on.empty()) {
      insert.BindNull().Bind("ready");
    } else {
      insert.Bind(job.depends_on).Bind("pending");
    }
    insert.Bind(campaign.max_attempts)
        .Bind(campaign.job_timeout_s)
        .Bind(now)
        .Bind(ToJson(job.position_rule).dump());
    // Dependants learn their content (an eval's position) when their dependency succeeds; until
    // then they keep its base. The others know it now, and need no base.
    const auto key = job.depends_on.empty() ? JobContentKey(job.content_base, p.kind, std::nullopt)
                                            : std::nullopt;
    insert.Bind(key ? std::nullopt : text_or_null(job.content_base))
        .Bind(key)
        .Bind(text_or_null(p.policy_sha256))
        .Run();
    if (key)
      cacheable.push_back(job.id);
  });
}

std::vector<ReadyJob> JobLedger::ListReady(std::size_t per_campaign) {
  // Indexed queries (jobs_ready_by_kind) per active campaign and kind, trains first: the cost
  // follows what is asked for, not how many jobs wait.
  std::vector<std::string> campaigns;
  Statement active =
      db_->Prepare("SELECT id FROM campaigns WHERE state = 'active' ORDER BY created_at, id");
  const ResultColumn campaign_column = active.Column("id");
  while (active.Step())
    campaigns.push_back(active.Text(campaign_column));
  Statement select = db_->Prepare(
      std::string("SELECT j.id, j.campaign_id, j.key, j.attempt, j.timeout_s, ") + kParamColumns +
      " FROM jobs j WHERE j.state = 'ready' AND j.campaign_id = ? AND j.kind = ? "
      // A job that waits for an identical one's result runs only if that one will not.
      "AND (j.cache_twin IS NULL OR NOT EXISTS (SELECT 1 FROM jobs t WHERE t.id = j.cache_twin "
      "AND t.state IN ('ready', 'running'))) "
      "ORDER BY j.seq LIMIT ?");
  const ResultColumn id = select.Column("id"), campaign_id = select.Column("campaign_id"),
                     key = select.Column("key"), attempt = select.Column("attempt"),
                     timeout_s = select.Column("timeout_s");
  const ParamColumns params(select);
  std::vector<ReadyJob> out;
  for (const auto& campaign : campaigns) {
    std::size_t taken = 0;
    for (const JobKind kind : kJobKinds) {
      if (per_campaign != 0 && taken >= per_campaign)
        break;
      select.Reset();
      select.Bind(campaign)
          .Bind(ToString(kind))
          .Bind(per_campaign == 0 ? std::int64_t{-1}
                                  : static_cast<std::int64_t>(per_campaign - taken));
      while (select.Step()) {
        ReadyJob job;
        job.id = select.Text(id);
        job.campaign_id = select.Text(campaign_id);
        job.key = select.Text(key);
        job.attempt = static_cast<int>(select.Int(attempt));
        job.timeout_s = select.Double(timeout_s);
        job.params = ReadParams(select, params, job.placement, store_.file());
        out.push_back(std::move(job));
        ++taken;
      }
    }
  }
  return out;
}

bool JobLedger::MarkRunning(const std::string& job_id, const std::string& worker_id, int slot,
                            int attempt) {
  db_->Prepare(
         "UPDATE jobs SET state = 'running', worker_id = ?, slot = ?, started_at = ?, "
         "finished_at = NULL, progress = NULL "
         "WHERE id = ? AND attempt = ? AND state = 'ready'")
      .Bind(worker_id)
      .Bind(slot)
      .Bind(store_.Now())
      .Bind(job_id)
      .Bind(attempt)
      .Run();
  return db_->Changes() == 1;
}

std::vector<RunningJob> JobLedger::ListRunning() {
  Statement select = db_->Prepare(std::string("SELECT ") + kRunningJobColumns +
                                  " FROM jobs WHERE state = 'running' ORDER BY started_at, id");
  const RunningJobColumns columns(select);
  std::vector<RunningJob> out;
  while (select.Step())
    out.push_back(ReadRunningJob(select, columns));
  return out;
}

std::vector<RunningSlot> JobLedger::RunningSlots() {
  Statement select = db_->Prepare(
      "SELECT COALESCE(worker_id, '') AS worker_id, campaign_id, COALESCE(slot, 0) AS slot "
      "FROM jobs WHERE state = 'running'");
  const ResultColumn worker_id = select.Column("worker_id"),
                     campaign_id = select.Column("campaign_id"), slot = select.Column("slot");
  std::vector<RunningSlot> out;
  while (select.Step()) {
    out.push_back(
        {select.Text(worker_id), select.Text(campaign_id), static_cast<int>(select.Int(slot))});
  }
  return out;
}

void JobLedger::SetProgress(const std::string& job_id, int attempt, const std::string& line,
                            const std::string& worker_id) {
  db_->Prepare(
         "UPDATE jobs SET progress = ? WHERE id = ? AND attempt = ? AND state = 'running' "
         "AND (? = '' OR worker_id = ?)")
      .Bind(line)
      .Bind(job_id)
      .Bind(attempt)
      .Bind(worker_id)
      .Bind(worker_id)
      .Run();
}

void JobLedger::UpsertWorker(const WorkerRecord& worker) {
  const double now = store_.Now();
  db_->Prepare(
         "INSERT INTO workers (id, host, pid, slots, busy, state, first_seen, last_seen) "
         "VALUES (?, ?, ?, ?, ?, 'alive', ?, ?) "
         "ON CONFLICT(id) DO UPDATE SET host = excluded.host, pid = excluded.pid, "
         "slots = excluded.slots, busy = excluded.busy, state = 'alive', "
         "last_seen = excluded.last_seen")
      .Bind(worker.id)
      .Bind(worker.host)
      .Bind(worker.pid)
      .Bind(worker.slots)
      .Bind(worker.busy)
      .Bind(now)
      .Bind(now)
      .Run();
}

void JobLedger::SetWorkerState(const std::string& worker_id, const std::string& state) {
  db_->Prepare("UPDATE workers SET state = ?, busy = 0, last_seen = ? WHERE id = ?")
      .Bind(state)
      .Bind(store_.Now())
      .Bind(worker_id)
      .Run();
}

void JobLedger::MarkAllWorkersLost() {
  db_->Prepare("UPDATE workers SET state = 'lost', busy = 0 WHERE state = 'alive'").Run();
}

}  // namespace rlpos
