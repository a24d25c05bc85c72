#include "store/results_store.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "campaign/job_content.h"
#include "scenario/placement_json.h"
#include "store/artifact_files.h"
#include "store/job_result.h"
#include "store/schema.h"
#include "store/sqlite_db.h"
#include "store/store_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

double SystemNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// The typed job columns, in the order ReadParams reads them.
constexpr const char* kParamColumns =
    "kind, scenario, train_seed, fidelity, train_episodes, positioner, rng_run, duration_s, "
    "warmup_s, overrides_json, x, y, z, positions_json";

std::string OverridesJson(const std::vector<ScenarioOverride>& overrides) {
  json out = json::array();
  for (const auto& o : overrides)
    out.push_back({o.path, o.value});
  return out.dump();
}

// The columns ReadRunningJob reads, in order.
constexpr const char* kRunningJobColumns =
    "id, campaign_id, COALESCE(worker_id, ''), COALESCE(slot, 0), attempt, started_at, timeout_s";

RunningJob ReadRunningJob(const Statement& row) {
  return {row.Text(0),
          row.Text(1),
          row.Text(2),
          static_cast<int>(row.Int(3)),
          static_cast<int>(row.Int(4)),
          row.Double(5),
          row.Double(6)};
}

// jobs.positions_json: every UAV's position of a placement of several, NULL for one (x, y, z).
std::optional<std::string> PositionsJson(const Placement& placement) {
  if (placement.size() < 2)
    return std::nullopt;
  return PlacementJson(placement).dump();
}

// The placement of x, y, z, positions_json starting at `first`: positions_json when set (several
// UAVs), else x, y, z when bound. Throws on a malformed positions_json.
std::optional<Placement> ReadPlacement(const Statement& row, int first) {
  if (const auto positions = row.OptionalText(first + 3)) {
    Placement placement;
    for (const auto& q : json::parse(*positions))
      placement.push_back({q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>()});
    return placement;
  }
  const auto x = row.OptionalDouble(first);
  const auto y = row.OptionalDouble(first + 1);
  const auto z = row.OptionalDouble(first + 2);
  if (x && y && z)
    return Placement{{*x, *y, *z}};
  return std::nullopt;
}

// Reads kParamColumns starting at `first`; sets `placement` from positions_json or x, y, z.
JobParams ReadParams(const Statement& row, int first, std::optional<Placement>& placement,
                     const std::string& file) {
  JobParams p;
  try {
    p.kind = ParseJobKind(row.Text(first));
    p.scenario = row.Text(first + 1);
    if (const auto seed = row.OptionalInt(first + 2)) {
      p.train_seed = static_cast<std::uint64_t>(*seed);
    }
    p.fidelity = row.OptionalText(first + 3).value_or("");
    if (const auto episodes = row.OptionalInt(first + 4)) {
      p.train_episodes = static_cast<int>(*episodes);
    }
    p.positioner = row.OptionalText(first + 5).value_or("");
    if (const auto run = row.OptionalInt(first + 6))
      p.rng_run = static_cast<std::uint64_t>(*run);
    p.duration_s = row.OptionalDouble(first + 7);
    p.warmup_s = row.OptionalDouble(first + 8);
    for (const auto& pair : json::parse(row.Text(first + 9))) {
      p.overrides.push_back({pair.at(0).get<std::string>(), pair.at(1).get<std::string>()});
    }
    placement = ReadPlacement(row, first + 10);
  } catch (const std::exception& e) {
    throw StoreError(file, std::string("malformed job row: ") + e.what());
  }
  return p;
}

bool SamePlacement(const Placement& a, const Placement& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), SamePosition);
}

CampaignProgress ReadProgress(const Statement& row) {
  CampaignProgress p;
  p.campaign_id = row.Text(0);
  p.name = row.Text(1);
  p.state = row.Text(2);
  p.total = static_cast<int>(row.Int(3));
  p.pending = static_cast<int>(row.Int(4));
  p.ready = static_cast<int>(row.Int(5));
  p.running = static_cast<int>(row.Int(6));
  p.succeeded = static_cast<int>(row.Int(7));
  p.failed = static_cast<int>(row.Int(8));
  p.cancelled = static_cast<int>(row.Int(9));
  p.cached = static_cast<int>(row.Int(10));
  return p;
}

constexpr const char* kProgressColumns =
    "SELECT campaign_id, name, state, total, pending, ready, running, succeeded, failed, "
    "cancelled, cached FROM v_campaign_progress";

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

ResultsStore::ResultsStore(const std::string& file, StoreOptions options)
    : options_(std::move(options)) {
  if (!options_.clock)
    options_.clock = SystemNow;
  db_ = std::make_unique<Database>(file, options_.read_only, options_.busy_timeout_ms);
  if (!options_.read_only) {
    // WAL: readers (status, report) never block the coordinator's writes, nor it them.
    Statement mode = db_->Prepare("PRAGMA journal_mode = WAL");
    if (!mode.Step() || mode.Text(0) != "wal") {
      throw StoreError(file, "cannot switch to WAL mode");
    }
    // WAL with synchronous NORMAL: a commit is durable against a crash of the coordinator and
    // stays consistent on power loss, which may lose the last commits (their jobs run again).
    // FULL would fsync on every job event; at thousands of jobs that is the coordinator's cost.
    db_->Exec("PRAGMA synchronous = NORMAL");
  }
  db_->Exec("PRAGMA foreign_keys = ON");
  MigrateSchema(*db_);
}

ResultsStore::~ResultsStore() = default;

const std::string& ResultsStore::file() const {
  return db_->file();
}

StoreBatch::StoreBatch(std::unique_ptr<Transaction> transaction)
    : transaction_(std::move(transaction)) {}
StoreBatch::~StoreBatch() = default;
StoreBatch::StoreBatch(StoreBatch&&) noexcept = default;
void StoreBatch::Commit() {
  transaction_->Commit();
}

StoreBatch ResultsStore::Batch() {
  return StoreBatch(std::make_unique<Transaction>(*db_));
}

std::vector<std::string> ResultsStore::CampaignBuilds(const std::string& campaign_id) {
  Statement select = db_->Prepare(
      "SELECT DISTINCT rlpos_version, ns3_version, torch_version, cyclonedds_version FROM jobs "
      "WHERE campaign_id = ? AND state = 'succeeded' AND rlpos_version IS NOT NULL "
      "ORDER BY 1, 2, 3, 4");
  select.Bind(campaign_id);
  std::vector<std::string> builds;
  while (select.Step()) {
    Provenance p;
    p.rlpos_version = select.Text(0);
    p.ns3_version = select.OptionalText(1).value_or("?");
    p.torch_version = select.OptionalText(2).value_or("?");
    p.cyclonedds_version = select.OptionalText(3).value_or("?");
    builds.push_back(DescribeBuild(p));
  }
  return builds;
}

int ResultsStore::SchemaVersion() {
  return ReadSchemaVersion(*db_);
}

double ResultsStore::Now() const {
  return options_.clock();
}

SubmitResult ResultsStore::Submit(const CampaignPlan& campaign) {
  Transaction transaction(*db_);
  SubmitResult result{campaign.id, false, 0};
  const std::string& spec_text = campaign.spec_json;
  Statement existing = db_->Prepare("SELECT spec_json FROM campaigns WHERE id = ?");
  existing.Bind(campaign.id);
  if (existing.Step()) {
    if (existing.Text(0) != spec_text) {
      // 48 bits of FNV-1a make this practically impossible; refuse rather than mix campaigns.
      throw StoreError(file(), "campaign id " + campaign.id + " is taken by another campaign");
    }
    Statement count = db_->Prepare("SELECT COUNT(*) FROM jobs WHERE campaign_id = ?");
    count.Bind(campaign.id).Step();
    result.jobs = static_cast<int>(count.Int(0));
    return result;  // the transaction rolls back: nothing was written
  }

  const double now = Now();
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
  Statement insert = db_->Prepare(
      "INSERT INTO jobs (id, campaign_id, seq, kind, key, scenario, label, rng_run, train_seed, "
      "fidelity, train_episodes, positioner, duration_s, warmup_s, overrides_json, "
      "depends_on, state, attempt, max_attempts, timeout_s, created_at, "
      "position_rule_json, content_base, cache_key) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
      "?, ?, ?, ?, 1, ?, ?, ?, ?, ?, ?)");
  std::vector<std::string> cacheable;  // ready jobs whose content is known
  int seq = 0;
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
    insert.Bind(key ? std::nullopt : text_or_null(job.content_base)).Bind(key).Run();
    if (key)
      cacheable.push_back(job.id);
  });
  if (campaign.use_cache) {
    for (const auto& id : cacheable)
      ResolveFromCache(id);
  }
  UpdateCampaignState(campaign.id);
  transaction.Commit();
  result.created = true;
  result.jobs = seq;
  return result;
}

std::vector<ReadyJob> ResultsStore::ListReady(std::size_t per_campaign) {
  // Indexed queries (jobs_ready_by_kind) per active campaign and kind, trains first: the cost
  // follows what is asked for, not how many jobs wait.
  std::vector<std::string> campaigns;
  Statement active =
      db_->Prepare("SELECT id FROM campaigns WHERE state = 'active' ORDER BY created_at, id");
  while (active.Step())
    campaigns.push_back(active.Text(0));
  Statement select = db_->Prepare(
      std::string("SELECT j.id, j.campaign_id, j.key, j.attempt, j.timeout_s, ") + kParamColumns +
      " FROM jobs j WHERE j.state = 'ready' AND j.campaign_id = ? AND j.kind = ? "
      // A job that waits for an identical one's result runs only if that one will not.
      "AND (j.cache_twin IS NULL OR NOT EXISTS (SELECT 1 FROM jobs t WHERE t.id = j.cache_twin "
      "AND t.state IN ('ready', 'running'))) "
      "ORDER BY j.seq LIMIT ?");
  std::vector<ReadyJob> out;
  for (const auto& campaign : campaigns) {
    std::size_t taken = 0;
    for (const char* kind : {"train", "position", "eval"}) {
      if (per_campaign != 0 && taken >= per_campaign)
        break;
      select.Reset();
      select.Bind(campaign).Bind(kind).Bind(
          per_campaign == 0 ? std::int64_t{-1} : static_cast<std::int64_t>(per_campaign - taken));
      while (select.Step()) {
        ReadyJob job;
        job.id = select.Text(0);
        job.campaign_id = select.Text(1);
        job.key = select.Text(2);
        job.attempt = static_cast<int>(select.Int(3));
        job.timeout_s = select.Double(4);
        job.params = ReadParams(select, 5, job.placement, file());
        out.push_back(std::move(job));
        ++taken;
      }
    }
  }
  return out;
}

bool ResultsStore::MarkRunning(const std::string& job_id, const std::string& worker_id, int slot,
                               int attempt) {
  db_->Prepare(
         "UPDATE jobs SET state = 'running', worker_id = ?, slot = ?, started_at = ?, "
         "finished_at = NULL, progress = NULL "
         "WHERE id = ? AND attempt = ? AND state = 'ready'")
      .Bind(worker_id)
      .Bind(slot)
      .Bind(Now())
      .Bind(job_id)
      .Bind(attempt)
      .Run();
  return db_->Changes() == 1;
}

JobUpdate ResultsStore::RecordSuccess(const std::string& job_id, int attempt, const json& result,
                                      const std::string& worker_id, const Provenance* provenance,
                                      const std::vector<ArtifactFile>& artifacts) {
  Transaction transaction(*db_);
  Statement select = db_->Prepare(
      "SELECT state, attempt, max_attempts, campaign_id, label, worker_id, kind, scenario, "
      "rng_run, x, y, z, positions_json FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return JobUpdate::kUnknown;
  if (select.Text(0) != "running" || select.Int(1) != attempt)
    return JobUpdate::kStale;
  if (!worker_id.empty() && select.OptionalText(5) != worker_id)
    return JobUpdate::kStale;
  const int max_attempts = static_cast<int>(select.Int(2));
  const std::string campaign_id = select.Text(3);
  const std::string label = select.Text(4);
  const JobKind kind = ParseJobKind(select.Text(6));
  const std::string scenario = select.Text(7);
  const std::optional<std::int64_t> rng_run = select.OptionalInt(8);
  std::optional<Placement> job_placement;
  try {
    job_placement = ReadPlacement(select, 9);
  } catch (const std::exception& e) {
    throw StoreError(file(), "job " + job_id + ": malformed positions_json: " + e.what());
  }
  select.Reset();  // done reading: the row is about to change

  // Check the result before anything is written: a malformed one is a failed attempt.
  EvalResult eval;
  Placement produced;
  try {
    if (kind == JobKind::kEval) {
      eval = ParseEvalResult(result);
      if (eval.run && rng_run && static_cast<std::int64_t>(*eval.run) != *rng_run) {
        throw std::invalid_argument("result is of RngRun " + std::to_string(*eval.run) +
                                    ", the job's is " + std::to_string(*rng_run));
      }
      if (job_placement && !SamePlacement(*job_placement, eval.placement))
        throw std::invalid_argument("result is of another placement than the job's");
    } else {
      produced = ProducedPlacement(result);
      if (produced.size() > 1 && HasOffsetDependants(job_id)) {
        throw std::invalid_argument("a placement of " + std::to_string(produced.size()) +
                                    " UAVs, but offset evals (defined for one) depend on it");
      }
    }
  } catch (const std::invalid_argument& e) {
    const JobUpdate update =
        FailAttempt(job_id, attempt, max_attempts, std::string("malformed result: ") + e.what());
    UpdateCampaignState(campaign_id);
    transaction.Commit();
    return update;
  }
  if (!artifacts.empty()) {
    try {
      StoreArtifacts(job_id, artifacts);
    } catch (const std::exception& e) {
      const JobUpdate update = FailAttempt(job_id, attempt, max_attempts,
                                           std::string("cannot store its artifacts: ") + e.what());
      UpdateCampaignState(campaign_id);
      transaction.Commit();
      return update;
    }
  }

  // One statement for the row: the result and, when given, where it came from.
  const auto text = [](const std::string& v) {
    return v.empty() ? std::nullopt : std::optional<std::string>(v);
  };
  const Provenance none;
  const Provenance& p = provenance ? *provenance : none;
  db_->Prepare(
         "UPDATE jobs SET state = 'succeeded', finished_at = ?, result_json = ?, error = NULL, "
         "host = COALESCE(?, host), rlpos_version = COALESCE(?, rlpos_version), "
         "ns3_version = COALESCE(?, ns3_version), torch_version = COALESCE(?, torch_version), "
         "cyclonedds_version = COALESCE(?, cyclonedds_version), "
         "scenario_sha256 = COALESCE(?, scenario_sha256) "
         "WHERE id = ? AND attempt = ? AND state = 'running'")
      .Bind(Now())
      .Bind(result.dump())
      .Bind(text(p.host))
      .Bind(text(p.rlpos_version))
      .Bind(text(p.ns3_version))
      .Bind(text(p.torch_version))
      .Bind(text(p.cyclonedds_version))
      .Bind(text(p.scenario_sha256))
      .Bind(job_id)
      .Bind(attempt)
      .Run();

  if (kind == JobKind::kEval) {
    InsertEvalMetrics(*db_, {job_id, campaign_id, scenario, label, rng_run.value_or(0)}, eval);
  } else {
    // Bind each dependent's position now: the row then shows exactly what it will run. A chunk
    // at a time: one baseline with RngRun 1..100000 has 100k dependants, never all in memory.
    Statement dependents = db_->Prepare(
        "SELECT rowid, id, position_rule_json, kind, content_base, state FROM jobs "
        "WHERE depends_on = ? AND rowid > ? ORDER BY rowid LIMIT 1024");
    Statement update = db_->Prepare(
        "UPDATE jobs SET x = ?, y = ?, z = ?, positions_json = ?, cache_key = ?, "
        "content_base = NULL, "
        "state = CASE state WHEN 'pending' THEN 'ready' ELSE state END WHERE id = ?");
    struct Bound {
      std::string id;
      Placement placement;
      std::optional<std::string> cache_key;
      bool released = false;  // pending -> ready now
    };
    std::vector<Bound> bound;
    for (std::int64_t after = 0;; bound.clear()) {
      dependents.Reset();
      dependents.Bind(job_id).Bind(after);
      while (dependents.Step()) {
        after = dependents.Int(0);
        const std::string id = dependents.Text(1);
        PositionRule rule;
        JobKind dependent_kind;
        try {
          rule = PositionRuleFromJson(json::parse(dependents.Text(2)));
          dependent_kind = ParseJobKind(dependents.Text(3));
        } catch (const std::exception& e) {
          throw StoreError(file(), "job " + id + ": bad position rule: " + e.what());
        }
        Placement placement = ApplyPositionRule(rule, produced);  // checked above: cannot throw
        auto key = JobContentKey(dependents.OptionalText(4).value_or(""), dependent_kind, placement);
        bound.push_back(
            {id, std::move(placement), std::move(key), dependents.Text(5) == "pending"});
      }
      dependents.Reset();
      if (bound.empty())
        break;
      for (const auto& b : bound) {
        update.Reset();
        update.Bind(b.placement.front().x)
            .Bind(b.placement.front().y)
            .Bind(b.placement.front().z)
            .Bind(PositionsJson(b.placement))
            .Bind(b.cache_key)
            .Bind(b.id)
            .Run();
      }
      update.Reset();
      for (const auto& b : bound) {
        if (b.released && b.cache_key)
          ResolveFromCache(b.id);
      }
    }
  }
  ServeWaiting(job_id);
  UpdateCampaignState(campaign_id);
  transaction.Commit();
  return JobUpdate::kSucceeded;
}

bool ResultsStore::HasOffsetDependants(const std::string& job_id) {
  Statement select = db_->Prepare(
      "SELECT 1 FROM jobs WHERE depends_on = ? AND json_extract(position_rule_json, '$.offset') != 0 "
      "LIMIT 1");
  select.Bind(job_id);
  return select.Step();
}

void ResultsStore::StoreArtifacts(const std::string& job_id,
                                  const std::vector<ArtifactFile>& artifacts) {
  // The files first, then the rows that list them: a row never names a missing file. A file
  // written for a commit that then fails is overwritten by the job's next success.
  Transaction rows(*db_);  // none of them if one file fails
  const std::string root = ArtifactsDirOf(file());
  Statement insert = db_->Prepare(
      "INSERT OR REPLACE INTO artifacts (job_id, name, path, sha256, bytes) VALUES (?, ?, ?, ?, "
      "?)");
  for (const auto& a : artifacts) {
    const std::string path = ArtifactRelativePath(job_id, a.name);
    WriteArtifactFile(root, path, a.data);
    insert.Reset();
    insert.Bind(job_id)
        .Bind(a.name)
        .Bind(path)
        .Bind(a.sha256)
        .Bind(static_cast<std::int64_t>(a.data.size()))
        .Run();
  }
  insert.Reset();
  rows.Commit();
}

JobUpdate ResultsStore::RecordFailure(const std::string& job_id, int attempt,
                                      const std::string& error, const std::string& worker_id) {
  Transaction transaction(*db_);
  Statement select = db_->Prepare(
      "SELECT state, attempt, max_attempts, campaign_id, worker_id FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return JobUpdate::kUnknown;
  if (select.Text(0) != "running" || select.Int(1) != attempt)
    return JobUpdate::kStale;
  if (!worker_id.empty() && select.OptionalText(4) != worker_id)
    return JobUpdate::kStale;
  const int max_attempts = static_cast<int>(select.Int(2));
  const std::string campaign_id = select.Text(3);
  select.Reset();
  const JobUpdate update = FailAttempt(job_id, attempt, max_attempts, error);
  UpdateCampaignState(campaign_id);
  transaction.Commit();
  return update;
}

JobUpdate ResultsStore::FailAttempt(const std::string& job_id, int attempt, int max_attempts,
                                    const std::string& error) {
  const double now = Now();
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

void ResultsStore::UpdateCampaignState(const std::string& campaign_id) {
  db_->Prepare(
         "UPDATE campaigns SET state = 'finished' WHERE id = ? AND state = 'active' AND NOT "
         "EXISTS (SELECT 1 FROM jobs WHERE campaign_id = ? AND state IN "
         "('pending', 'ready', 'running'))")
      .Bind(campaign_id)
      .Bind(campaign_id)
      .Run();
}

void ResultsStore::RequireCampaign(const std::string& campaign_id) {
  Statement select = db_->Prepare("SELECT 1 FROM campaigns WHERE id = ?");
  select.Bind(campaign_id);
  if (!select.Step())
    throw StoreError(file(), "no campaign \"" + campaign_id + "\"");
}

std::vector<std::string> ResultsStore::RequeueWorker(const std::string& worker_id) {
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
  while (select.Step()) {
    held.push_back({select.Text(0), static_cast<int>(select.Int(1)),
                    static_cast<int>(select.Int(2)), select.Text(3)});
  }
  select.Reset();
  std::vector<std::string> ids;
  const std::string why = "worker " + worker_id + " was lost";
  for (const auto& h : held) {
    const int losses = h.infra_losses + 1;
    if (losses > options_.max_infra_losses) {
      // A job that keeps taking its worker down must not loop forever: fail it for good.
      FailAttempt(h.id, h.attempt, h.attempt,
                  why + ": " + std::to_string(losses) +
                      " infrastructure losses, more than the cap of " +
                      std::to_string(options_.max_infra_losses));
    } else {
      // Not the job's fault: a new attempt (the lost one's results become stale) that does not
      // use the job's retries.
      db_->Prepare(
             "UPDATE jobs SET state = 'ready', attempt = attempt + 1, "
             "max_attempts = max_attempts + 1, infra_losses = ?, worker_id = NULL, error = ?, "
             "finished_at = ? WHERE id = ? AND attempt = ?")
          .Bind(losses)
          .Bind(why)
          .Bind(Now())
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

std::vector<RunningJob> ResultsStore::ListRunning() {
  Statement select = db_->Prepare(std::string("SELECT ") + kRunningJobColumns +
                                  " FROM jobs WHERE state = 'running' ORDER BY started_at, id");
  std::vector<RunningJob> out;
  while (select.Step())
    out.push_back(ReadRunningJob(select));
  return out;
}

std::vector<ResultsStore::RunningSlot> ResultsStore::RunningSlots() {
  Statement select = db_->Prepare(
      "SELECT COALESCE(worker_id, ''), campaign_id, COALESCE(slot, 0) FROM jobs "
      "WHERE state = 'running'");
  std::vector<RunningSlot> out;
  while (select.Step())
    out.push_back({select.Text(0), select.Text(1), static_cast<int>(select.Int(2))});
  return out;
}

std::vector<RunningJob> ResultsStore::CancelCampaign(const std::string& campaign_id) {
  Transaction transaction(*db_);
  RequireCampaign(campaign_id);
  Statement running =
      db_->Prepare(std::string("SELECT ") + kRunningJobColumns +
                   " FROM jobs WHERE campaign_id = ? AND state = 'running' ORDER BY id");
  running.Bind(campaign_id);
  std::vector<RunningJob> stopped;
  while (running.Step())
    stopped.push_back(ReadRunningJob(running));
  db_->Prepare(
         "UPDATE jobs SET state = 'cancelled', finished_at = ? "
         "WHERE campaign_id = ? AND state IN ('pending', 'ready', 'running')")
      .Bind(Now())
      .Bind(campaign_id)
      .Run();
  db_->Prepare("UPDATE campaigns SET state = 'cancelled' WHERE id = ? AND state = 'active'")
      .Bind(campaign_id)
      .Run();
  transaction.Commit();
  return stopped;
}

int ResultsStore::RetryFailed(const std::string& campaign_id) {
  Transaction transaction(*db_);
  RequireCampaign(campaign_id);
  Statement revive = db_->Prepare(
      "SELECT id FROM jobs WHERE campaign_id = ? AND state IN ('failed', 'cancelled')");
  revive.Bind(campaign_id);
  std::vector<std::string> revived_ids;
  while (revive.Step())
    revived_ids.push_back(revive.Text(0));
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
      ResolveFromCache(id);
    UpdateCampaignState(campaign_id);
  }
  transaction.Commit();
  return revived;
}

CampaignProgress ResultsStore::Progress(const std::string& campaign_id) {
  Statement select = db_->Prepare(std::string(kProgressColumns) + " WHERE campaign_id = ?");
  select.Bind(campaign_id);
  if (!select.Step())
    throw StoreError(file(), "no campaign \"" + campaign_id + "\"");
  return ReadProgress(select);
}

std::vector<CampaignProgress> ResultsStore::AllProgress() {
  Statement select =
      db_->Prepare(std::string(kProgressColumns) + " ORDER BY created_utc, campaign_id");
  std::vector<CampaignProgress> out;
  while (select.Step())
    out.push_back(ReadProgress(select));
  return out;
}

std::optional<JobRecord> ResultsStore::GetJob(const std::string& job_id) {
  Statement select = db_->Prepare(
      std::string("SELECT id, campaign_id, key, label, state, depends_on, attempt, max_attempts, "
                  "timeout_s, worker_id, error, result_json, COALESCE(slot, 0), ") +
      kParamColumns + " FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return std::nullopt;
  JobRecord r;
  r.id = select.Text(0);
  r.campaign_id = select.Text(1);
  r.key = select.Text(2);
  r.label = select.Text(3);
  r.state = select.Text(4);
  r.depends_on = select.OptionalText(5).value_or("");
  r.attempt = static_cast<int>(select.Int(6));
  r.max_attempts = static_cast<int>(select.Int(7));
  r.timeout_s = select.Double(8);
  r.worker_id = select.OptionalText(9);
  r.error = select.OptionalText(10);
  if (const auto result = select.OptionalText(11))
    r.result = json::parse(*result);
  r.slot = static_cast<int>(select.Int(12));
  r.params = ReadParams(select, 13, r.placement, file());
  return r;
}

std::vector<MetricRow> ResultsStore::Metrics(const std::string& campaign_id) {
  return ReadMetricRows(*db_, campaign_id);
}

std::vector<UavMetricRow> ResultsStore::UavMetrics(const std::string& campaign_id) {
  return ReadUavMetricRows(*db_, campaign_id);
}

}  // namespace rlpos
