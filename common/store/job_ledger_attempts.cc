// The ledger's attempts: a failed attempt, a lost worker's jobs, a cancelled or retried
// campaign.
#include "common/store/job_ledger.h"
#include "common/store/job_rows.h"
#include "common/store/result_cache.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"

namespace rlpos {

JobUpdate JobLedger::RecordFailure(const std::string& job_id, int attempt, const std::string& error,
                                   const std::string& worker_id) {
  Transaction transaction(*db_);
  Statement select = db_->Prepare(
      "SELECT state, attempt, max_attempts, campaign_id, worker_id FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return JobUpdate::kUnknown;
  if (select.Text(select.Column("state")) != "running" ||
      select.Int(select.Column("attempt")) != attempt)
    return JobUpdate::kStale;
  if (!worker_id.empty() && select.OptionalText(select.Column("worker_id")) != worker_id)
    return JobUpdate::kStale;
  const int max_attempts = static_cast<int>(select.Int(select.Column("max_attempts")));
  const std::string campaign_id = select.Text(select.Column("campaign_id"));
  select.Reset();
  const JobUpdate update = FailAttempt(job_id, attempt, max_attempts, error);
  UpdateCampaignState(campaign_id);
  transaction.Commit();
  return update;
}

JobUpdate JobLedger::FailAttempt(const std::string& job_id, int attempt, int max_attempts,
                                 const std::string& error) {
  const double now = store_.Now();
  if (attempt < max_attempts) {
    // The last error stays visible while the job waits for its next attempt.
    db_->Prepare(
           "UPDATE jobs SET state = 'ready', attempt = attempt + 1, worker_id = NULL, "
           "error = ?, finished_at = ? WHERE id = ? AND attempt = ?")
        .Bind(error)
        .Bind(now)
        .Bind(job_id)
        .Bind(attempt)
        .Run();
    return JobUpdate::kRetrying;
  }
  db_->Prepare(
         "UPDATE jobs SET state = 'failed', error = ?, finished_at = ? "
         "WHERE id = ? AND attempt = ?")
      .Bind(error)
      .Bind(now)
      .Bind(job_id)
      .Bind(attempt)
      .Run();
  // Jobs waiting for this one's position can never run: fail them now, so the campaign can
  // finish and RetryFailed brings them back together with it.
  db_->Prepare(
         "UPDATE jobs SET state = 'failed', error = ?, finished_at = ? "
         "WHERE depends_on = ? AND state = 'pending'")
      .Bind("dependency " + job_id + " failed")
      .Bind(now)
      .Bind(job_id)
      .Run();
  return JobUpdate::kFailed;
}

void JobLedger::UpdateCampaignState(const std::string& campaign_id) {
  db_->Prepare(
         "UPDATE campaigns SET state = 'finished' WHERE id = ? AND state = 'active' AND NOT "
         "EXISTS (SELECT 1 FROM jobs WHERE campaign_id = ? AND state IN "
         "('pending', 'ready', 'running'))")
      .Bind(campaign_id)
      .Bind(campaign_id)
      .Run();
}

std::vector<std::string> JobLedger::RequeueWorker(const std::string& worker_id) {
  Transaction transaction(*db_);
  Statement select = db_->Prepare(
      "SELECT id, attempt, infra_losses, campaign_id FROM jobs "
      "WHERE worker_id = ? AND state = 'running' ORDER BY id");
  select.Bind(worker_id);
  struct Held {
    std::string id;
    int attempt, infra_losses;
    std::string campaign_id;
  };
  std::vector<Held> held;
  const ResultColumn id = select.Column("id"), attempt = select.Column("attempt"),
                     infra_losses = select.Column("infra_losses"),
                     campaign_id = select.Column("campaign_id");
  while (select.Step()) {
    held.push_back({select.Text(id), static_cast<int>(select.Int(attempt)),
                    static_cast<int>(select.Int(infra_losses)), select.Text(campaign_id)});
  }
  select.Reset();
  std::vector<std::string> ids;
  const std::string why = "worker " + worker_id + " was lost";
  for (const auto& h : held) {
    const int losses = h.infra_losses + 1;
    if (losses > store_.options().max_infra_losses) {
      // A job that keeps taking its worker down must not loop forever: fail it for good.
      FailAttempt(h.id, h.attempt, h.attempt,
                  why + ": " + std::to_string(losses) +
                      " infrastructure losses, more than the cap of " +
                      std::to_string(store_.options().max_infra_losses));
    } else {
      // Not the job's fault: a new attempt (the lost one's results become stale) that does not
      // use the job's retries.
      db_->Prepare(
             "UPDATE jobs SET state = 'ready', attempt = attempt + 1, "
             "max_attempts = max_attempts + 1, infra_losses = ?, worker_id = NULL, error = ?, "
             "finished_at = ? WHERE id = ? AND attempt = ?")
          .Bind(losses)
          .Bind(why)
          .Bind(store_.Now())
          .Bind(h.id)
          .Bind(h.attempt)
          .Run();
    }
    UpdateCampaignState(h.campaign_id);
    ids.push_back(h.id);
  }
  transaction.Commit();
  return ids;
}

std::vector<RunningJob> JobLedger::CancelCampaign(const std::string& campaign_id) {
  Transaction transaction(*db_);
  store_.RequireCampaign(campaign_id);
  Statement running =
      db_->Prepare(std::string("SELECT ") + kRunningJobColumns +
                   " FROM jobs WHERE campaign_id = ? AND state = 'running' ORDER BY id");
  running.Bind(campaign_id);
  const RunningJobColumns columns(running);
  std::vector<RunningJob> stopped;
  while (running.Step())
    stopped.push_back(ReadRunningJob(running, columns));
  db_->Prepare(
         "UPDATE jobs SET state = 'cancelled', finished_at = ? "
         "WHERE campaign_id = ? AND state IN ('pending', 'ready', 'running')")
      .Bind(store_.Now())
      .Bind(campaign_id)
      .Run();
  db_->Prepare("UPDATE campaigns SET state = 'cancelled' WHERE id = ? AND state = 'active'")
      .Bind(campaign_id)
      .Run();
  transaction.Commit();
  return stopped;
}

int JobLedger::RetryFailed(const std::string& campaign_id) {
  Transaction transaction(*db_);
  store_.RequireCampaign(campaign_id);
  Statement revive = db_->Prepare(
      "SELECT id FROM jobs WHERE campaign_id = ? AND state IN ('failed', 'cancelled')");
  revive.Bind(campaign_id);
  std::vector<std::string> revived_ids;
  const ResultColumn id_column = revive.Column("id");
  while (revive.Step())
    revived_ids.push_back(revive.Text(id_column));
  revive.Reset();
  // A job whose dependency has not succeeded (it is being retried too) waits as pending.
  // attempt + 1 makes any late result of the old attempt stale.
  db_->Prepare(
         "UPDATE jobs SET "
         "state = CASE WHEN depends_on IS NULL OR "
         "  (SELECT d.state FROM jobs d WHERE d.id = jobs.depends_on) = 'succeeded' "
         "  THEN 'ready' ELSE 'pending' END, "
         "max_attempts = attempt + (SELECT c.max_attempts FROM campaigns c "
         "  WHERE c.id = jobs.campaign_id), "
         "attempt = attempt + 1, infra_losses = 0, worker_id = NULL, error = NULL, "
         "started_at = NULL, finished_at = NULL "
         "WHERE campaign_id = ? AND state IN ('failed', 'cancelled')")
      .Bind(campaign_id)
      .Run();
  const int revived = db_->Changes();
  if (revived > 0) {
    db_->Prepare("UPDATE campaigns SET state = 'active' WHERE id = ?").Bind(campaign_id).Run();
    // What another campaign computed meanwhile need not run again.
    for (const auto& id : revived_ids)
      cache_.ResolveFromCache(id);
    UpdateCampaignState(campaign_id);
  }
  transaction.Commit();
  return revived;
}

}  // namespace rlpos
