#include "common/store/schema.h"

#include <algorithm>

#include "common/store/legacy_argv.h"
#include "common/store/metric_columns.h"
#include "common/store/store_error.h"

namespace rlpos {
namespace {

// Version 1: campaigns, jobs, metrics, artifacts and the documented views.
// Timestamps are seconds since the Unix epoch (REAL); the views show them as UTC text.
constexpr const char* kVersion1 = R"sql(
CREATE TABLE campaigns (
  id            TEXT PRIMARY KEY,
  name          TEXT NOT NULL,
  spec_json     TEXT NOT NULL,
  created_at    REAL NOT NULL,
  state         TEXT NOT NULL CHECK (state IN ('active', 'cancelled', 'finished')),
  max_attempts  INTEGER NOT NULL CHECK (max_attempts >= 1),
  job_timeout_s REAL NOT NULL CHECK (job_timeout_s > 0)
);

CREATE TABLE jobs (
  id                 TEXT PRIMARY KEY,
  campaign_id        TEXT NOT NULL REFERENCES campaigns(id),
  seq                INTEGER NOT NULL,
  kind               TEXT NOT NULL CHECK (kind IN ('train', 'position', 'eval')),
  key                TEXT NOT NULL,
  scenario           TEXT NOT NULL,
  label              TEXT NOT NULL,
  rng_run            INTEGER,
  train_seed         INTEGER,
  depends_on         TEXT REFERENCES jobs(id),
  state              TEXT NOT NULL CHECK (state IN
                       ('pending', 'ready', 'running', 'succeeded', 'failed', 'cancelled')),
  attempt            INTEGER NOT NULL CHECK (attempt >= 1),
  max_attempts       INTEGER NOT NULL CHECK (max_attempts >= 1),
  timeout_s          REAL NOT NULL CHECK (timeout_s > 0),
  worker_id          TEXT,
  created_at         REAL NOT NULL,
  started_at         REAL,
  finished_at        REAL,
  error              TEXT,
  argv_json          TEXT NOT NULL,
  position_rule_json TEXT NOT NULL,
  result_json        TEXT,
  UNIQUE (campaign_id, key)
);
CREATE INDEX jobs_by_state ON jobs(state, campaign_id, seq);
CREATE INDEX jobs_by_dependency ON jobs(depends_on);
CREATE INDEX jobs_by_worker ON jobs(worker_id, state);

CREATE TABLE metrics (
  job_id                    TEXT PRIMARY KEY REFERENCES jobs(id),
  campaign_id               TEXT NOT NULL REFERENCES campaigns(id),
  scenario                  TEXT NOT NULL,
  label                     TEXT NOT NULL,
  rng_run                   INTEGER NOT NULL,
  aggregate_throughput_mbps REAL NOT NULL,
  mean_delay_ms             REAL,
  loss_ratio                REAL,
  n_los                     INTEGER NOT NULL,
  n_ues                     INTEGER NOT NULL,
  demands_met               INTEGER NOT NULL,
  min_snr_db                REAL,
  x                         REAL NOT NULL,
  y                         REAL NOT NULL,
  z                         REAL NOT NULL
);
CREATE INDEX metrics_by_campaign ON metrics(campaign_id, scenario, label, rng_run);

CREATE TABLE artifacts (
  job_id TEXT NOT NULL REFERENCES jobs(id),
  name   TEXT NOT NULL,
  path   TEXT NOT NULL,
  PRIMARY KEY (job_id, name)
);

CREATE VIEW v_eval_runs AS
SELECT c.id AS campaign_id, c.name AS campaign, m.scenario, m.label AS positioner, m.rng_run,
       m.aggregate_throughput_mbps AS throughput_mbps, m.mean_delay_ms AS delay_ms,
       m.loss_ratio, m.n_los, m.n_ues, m.demands_met, m.min_snr_db, m.x, m.y, m.z,
       m.job_id, datetime(j.finished_at, 'unixepoch') AS finished_utc
FROM metrics m
JOIN campaigns c ON c.id = m.campaign_id
JOIN jobs j ON j.id = m.job_id;

CREATE VIEW v_campaign_progress AS
SELECT c.id AS campaign_id, c.name, c.state, datetime(c.created_at, 'unixepoch') AS created_utc,
       COUNT(j.id) AS total,
       COALESCE(SUM(j.state = 'pending'), 0) AS pending,
       COALESCE(SUM(j.state = 'ready'), 0) AS ready,
       COALESCE(SUM(j.state = 'running'), 0) AS running,
       COALESCE(SUM(j.state = 'succeeded'), 0) AS succeeded,
       COALESCE(SUM(j.state = 'failed'), 0) AS failed,
       COALESCE(SUM(j.state = 'cancelled'), 0) AS cancelled
FROM campaigns c
LEFT JOIN jobs j ON j.campaign_id = c.id
GROUP BY c.id;
)sql";

// Version 2: the workers the coordinator has seen, and the latest progress line of each running
// job, so that `status` (another process) can show them.
constexpr const char* kVersion2 = R"sql(
ALTER TABLE jobs ADD COLUMN progress TEXT;

CREATE TABLE workers (
  id         TEXT PRIMARY KEY,
  host       TEXT NOT NULL,
  pid        INTEGER NOT NULL,
  slots      INTEGER NOT NULL CHECK (slots >= 1),
  busy       INTEGER NOT NULL CHECK (busy >= 0),
  state      TEXT NOT NULL CHECK (state IN ('alive', 'lost', 'stopped')),
  first_seen REAL NOT NULL,
  last_seen  REAL NOT NULL
);
)sql";

// Version 3: typed jobs. What a job runs is columns (and a JSON list of the scenario's
// overrides), no longer an rlpos-sim command line; an eval's position is bound into x, y, z when
// its dependency succeeds. Version 2's argv_json is converted, then dropped.
constexpr const char* kVersion3 = R"sql(
ALTER TABLE jobs ADD COLUMN fidelity TEXT;
ALTER TABLE jobs ADD COLUMN train_episodes INTEGER;
ALTER TABLE jobs ADD COLUMN positioner TEXT;
ALTER TABLE jobs ADD COLUMN duration_s REAL;
ALTER TABLE jobs ADD COLUMN warmup_s REAL;
ALTER TABLE jobs ADD COLUMN overrides_json TEXT NOT NULL DEFAULT '[]';
ALTER TABLE jobs ADD COLUMN x REAL;
ALTER TABLE jobs ADD COLUMN y REAL;
ALTER TABLE jobs ADD COLUMN z REAL;
)sql";

constexpr const char* kVersion3After = R"sql(
ALTER TABLE jobs DROP COLUMN argv_json;
)sql";

// Version 4: ready jobs by kind, so that the scheduler reads only as many as it can place
// (trains first, then positions, then evals) however many wait.
constexpr const char* kVersion4 = R"sql(
CREATE INDEX jobs_ready_by_kind ON jobs(state, campaign_id, kind, seq);
)sql";

// Version 5: losses of a job's worker (killed, host gone) counted apart from its own failures:
// they give a new attempt without using the job's retries, up to a cap.
constexpr const char* kVersion5 = R"sql(
ALTER TABLE jobs ADD COLUMN infra_losses INTEGER NOT NULL DEFAULT 0;
)sql";

// Version 6: provenance of each result: the host that ran it, its build, and the sha256 of the
// scenario document it ran.
constexpr const char* kVersion6 = R"sql(
ALTER TABLE jobs ADD COLUMN host TEXT;
ALTER TABLE jobs ADD COLUMN rlpos_version TEXT;
ALTER TABLE jobs ADD COLUMN ns3_version TEXT;
ALTER TABLE jobs ADD COLUMN torch_version TEXT;
ALTER TABLE jobs ADD COLUMN cyclonedds_version TEXT;
ALTER TABLE jobs ADD COLUMN scenario_sha256 TEXT;
)sql";

// Version 7: the result cache and artifacts that come home.
//  - campaigns.use_cache: 0 when submitted with --no-cache (its jobs always run);
//  - jobs.content_base: hash of what the job runs but an eval's position
//    (campaign/job_content.h), kept only until cache_key, its full content, is known; cached_from:
//    the succeeded job whose result this one took; cache_twin: an identical job, ready or running,
//    whose result this one waits for instead of running too;
//  - artifacts: each file's sha256 and size; path is relative to the artifacts folder;
//  - fewer indexes that hold a job's state, each updated on every state change (three per
//    job): jobs_by_state goes (jobs_ready_by_kind starts with the same columns), and the
//    indexes by worker and by cache key leave the state out.
constexpr const char* kVersion7 = R"sql(
ALTER TABLE campaigns ADD COLUMN use_cache INTEGER NOT NULL DEFAULT 1;
ALTER TABLE jobs ADD COLUMN content_base TEXT;
ALTER TABLE jobs ADD COLUMN cache_key TEXT;
ALTER TABLE jobs ADD COLUMN cached_from TEXT REFERENCES jobs(id);
ALTER TABLE jobs ADD COLUMN cache_twin TEXT REFERENCES jobs(id);
CREATE INDEX jobs_by_cache_key ON jobs(cache_key) WHERE cache_key IS NOT NULL;
CREATE INDEX jobs_by_cache_twin ON jobs(cache_twin) WHERE cache_twin IS NOT NULL;
ALTER TABLE artifacts ADD COLUMN sha256 TEXT;
ALTER TABLE artifacts ADD COLUMN bytes INTEGER;
DROP INDEX jobs_by_state;
DROP INDEX jobs_by_worker;
CREATE INDEX jobs_by_worker ON jobs(worker_id);
)sql";

// Version 8: jobs.slot, which of its worker's slots runs a running job (the DDS instance of its
// assignment, idl/rlpos_messages.idl); a restarted coordinator gives it back to the same slot.
// v_campaign_progress counts the jobs served from the result cache.
constexpr const char* kVersion8 = R"sql(
ALTER TABLE jobs ADD COLUMN slot INTEGER;
DROP VIEW v_campaign_progress;
CREATE VIEW v_campaign_progress AS
SELECT c.id AS campaign_id, c.name, c.state, datetime(c.created_at, 'unixepoch') AS created_utc,
       COUNT(j.id) AS total,
       COALESCE(SUM(j.state = 'pending'), 0) AS pending,
       COALESCE(SUM(j.state = 'ready'), 0) AS ready,
       COALESCE(SUM(j.state = 'running'), 0) AS running,
       COALESCE(SUM(j.state = 'succeeded'), 0) AS succeeded,
       COALESCE(SUM(j.state = 'failed'), 0) AS failed,
       COALESCE(SUM(j.state = 'cancelled'), 0) AS cancelled,
       COALESCE(SUM(j.state = 'succeeded' AND j.cached_from IS NOT NULL), 0) AS cached
FROM campaigns c
LEFT JOIN jobs j ON j.campaign_id = c.id
GROUP BY c.id;
)sql";

// Version 9: each eval's worst UE throughput and Jain's fairness index over its UEs'
// throughputs (NULL for runs recorded before, and where no UE received anything).
constexpr const char* kVersion9 = R"sql(
ALTER TABLE metrics ADD COLUMN worst_ue_throughput_mbps REAL;
ALTER TABLE metrics ADD COLUMN jain_fairness REAL;
DROP VIEW v_eval_runs;
CREATE VIEW v_eval_runs AS
SELECT c.id AS campaign_id, c.name AS campaign, m.scenario, m.label AS positioner, m.rng_run,
       m.aggregate_throughput_mbps AS throughput_mbps, m.mean_delay_ms AS delay_ms,
       m.loss_ratio, m.n_los, m.n_ues, m.demands_met, m.min_snr_db, m.x, m.y, m.z,
       m.job_id, datetime(j.finished_at, 'unixepoch') AS finished_utc,
       m.worst_ue_throughput_mbps AS worst_ue_mbps, m.jain_fairness
FROM metrics m
JOIN campaigns c ON c.id = m.campaign_id
JOIN jobs j ON j.id = m.job_id;
)sql";

// Version 10: several UAVs.
//  - jobs.positions_json: an eval's placement when it has several UAVs, [[x, y, z], ...] in the
//    scenario's order (x, y, z keep the first UAV's; NULL for one UAV);
//  - uav_metrics: each UAV's share of each eval (one row for a single-UAV eval, named 'uav',
//    also for the evals recorded before, from their totals); metrics.x, y, z are the first UAV's.
constexpr const char* kVersion10 = R"sql(
ALTER TABLE jobs ADD COLUMN positions_json TEXT;

CREATE TABLE uav_metrics (
  job_id                   TEXT NOT NULL REFERENCES jobs(id),
  uav                      INTEGER NOT NULL CHECK (uav >= 0),
  name                     TEXT NOT NULL,
  campaign_id              TEXT NOT NULL REFERENCES campaigns(id),
  scenario                 TEXT NOT NULL,
  label                    TEXT NOT NULL,
  rng_run                  INTEGER NOT NULL,
  ues_served               INTEGER NOT NULL,
  throughput_mbps          REAL NOT NULL,
  mean_delay_ms            REAL,
  loss_ratio               REAL,
  n_los                    INTEGER NOT NULL,
  worst_ue_throughput_mbps REAL,
  jain_fairness            REAL,
  x                        REAL NOT NULL,
  y                        REAL NOT NULL,
  z                        REAL NOT NULL,
  PRIMARY KEY (job_id, uav)
);
CREATE INDEX uav_metrics_by_campaign ON uav_metrics(campaign_id, scenario, label, rng_run);

INSERT INTO uav_metrics (job_id, uav, name, campaign_id, scenario, label, rng_run, ues_served,
                         throughput_mbps, mean_delay_ms, loss_ratio, n_los,
                         worst_ue_throughput_mbps, jain_fairness, x, y, z)
SELECT job_id, 0, 'uav', campaign_id, scenario, label, rng_run, n_ues, aggregate_throughput_mbps,
       mean_delay_ms, loss_ratio, n_los, worst_ue_throughput_mbps, jain_fairness, x, y, z
FROM metrics;

CREATE VIEW v_eval_uavs AS
SELECT c.id AS campaign_id, c.name AS campaign, u.scenario, u.label AS positioner, u.rng_run,
       u.uav, u.name AS uav_name, u.ues_served, u.throughput_mbps, u.mean_delay_ms AS delay_ms,
       u.loss_ratio, u.n_los, u.worst_ue_throughput_mbps AS worst_ue_mbps, u.jain_fairness,
       u.x, u.y, u.z, u.job_id
FROM uav_metrics u
JOIN campaigns c ON c.id = u.campaign_id;
)sql";

void ConvertArgvColumns(Database& db) {
  struct Row {
    std::string id;
    LegacyJobFields fields;
  };
  std::vector<Row> rows;
  Statement select = db.Prepare("SELECT id, argv_json FROM jobs");
  const ResultColumn id = select.Column("id"), argv_json = select.Column("argv_json");
  while (select.Step()) {
    try {
      rows.push_back({select.Text(id), LegacyJobFieldsFromArgv(select.Text(argv_json))});
    } catch (const std::exception& e) {
      throw StoreError(db.file(),
                       "job " + select.Text(id) + ": cannot read argv_json: " + e.what());
    }
  }
  select.Reset();
  Statement update = db.Prepare(
      "UPDATE jobs SET fidelity = ?, positioner = ?, duration_s = ?, overrides_json = ?, x = ?, "
      "y = ?, z = ? WHERE id = ?");
  for (const auto& row : rows) {
    const auto& f = row.fields;
    update.Reset();
    update.Bind(f.fidelity)
        .Bind(f.positioner)
        .Bind(f.duration_s)
        .Bind(f.overrides_json)
        .Bind(f.position ? std::optional<double>(f.position->x) : std::nullopt)
        .Bind(f.position ? std::optional<double>(f.position->y) : std::nullopt)
        .Bind(f.position ? std::optional<double>(f.position->z) : std::nullopt)
        .Bind(row.id)
        .Run();
  }
}

}  // namespace

// Version 12: the policy a named-policy rl position job flies (its bundle's sha256; the bundle
// is kept beside the database, in <artifacts>/policies/<sha256>/).
constexpr const char* kVersion12 = R"sql(
ALTER TABLE jobs ADD COLUMN policy_sha256 TEXT;
)sql";

// Version 13: runs in which the UEs walk and the UAVs follow (track jobs).
//  - jobs.kind may be 'track' (AllowTrackJobs);
//  - track_runs: one row per track job, its metrics over time (common/metrics/track_metrics.h:
//    each kTrackMetrics key is a column);
//  - track_intervals: its intervals, in order: the metrics of each and where the UAVs were at its
//    end ([[x, y, z], ...] in the scenario's order).
constexpr const char* kVersion13 = R"sql(
CREATE TABLE track_runs (
  job_id               TEXT PRIMARY KEY REFERENCES jobs(id),
  campaign_id          TEXT NOT NULL REFERENCES campaigns(id),
  scenario             TEXT NOT NULL,
  label                TEXT NOT NULL,
  rng_run              INTEGER NOT NULL,
  fidelity             TEXT NOT NULL,
  duration_s           REAL NOT NULL,
  decision_interval_s  REAL NOT NULL,
  intervals            INTEGER NOT NULL,
  scored_intervals     INTEGER NOT NULL,
  mean_reward          REAL NOT NULL,
  reward_p5            REAL NOT NULL,
  mean_throughput_mbps REAL NOT NULL,
  throughput_p5_mbps   REAL NOT NULL,
  mean_delay_ms        REAL,
  los_share            REAL NOT NULL,
  los_share_p5         REAL NOT NULL,
  outage_share         REAL NOT NULL,
  demands_met_share_p5 REAL NOT NULL,
  distance_flown_m     REAL NOT NULL,
  handovers            REAL NOT NULL
);
CREATE INDEX track_runs_by_campaign ON track_runs(campaign_id, scenario, label, rng_run);

CREATE TABLE track_intervals (
  job_id            TEXT NOT NULL REFERENCES jobs(id),
  interval          INTEGER NOT NULL CHECK (interval >= 0),
  campaign_id       TEXT NOT NULL REFERENCES campaigns(id),
  scenario          TEXT NOT NULL,
  label             TEXT NOT NULL,
  rng_run           INTEGER NOT NULL,
  time_s            REAL NOT NULL,
  scored            INTEGER NOT NULL CHECK (scored IN (0, 1)),
  reward            REAL NOT NULL,
  throughput_mbps   REAL NOT NULL,
  delay_ms          REAL,
  los_share         REAL NOT NULL,
  demands_met_share REAL NOT NULL,
  positions_json    TEXT NOT NULL,
  PRIMARY KEY (job_id, interval)
);
CREATE INDEX track_intervals_by_campaign
  ON track_intervals(campaign_id, scenario, label, rng_run, interval);

CREATE VIEW v_track_runs AS
SELECT c.id AS campaign_id, c.name AS campaign, t.scenario, t.label AS positioner, t.rng_run,
       t.fidelity, t.duration_s, t.decision_interval_s, t.intervals, t.scored_intervals,
       t.mean_reward, t.reward_p5, t.mean_throughput_mbps, t.throughput_p5_mbps,
       t.mean_delay_ms, t.los_share, t.los_share_p5, t.outage_share, t.demands_met_share_p5,
       t.distance_flown_m, t.handovers, t.job_id
FROM track_runs t
JOIN campaigns c ON c.id = t.campaign_id;

CREATE VIEW v_track_intervals AS
SELECT c.id AS campaign_id, c.name AS campaign, i.scenario, i.label AS positioner, i.rng_run,
       i.interval, i.time_s, i.scored, i.reward, i.throughput_mbps, i.delay_ms, i.los_share,
       i.demands_met_share, i.positions_json, i.job_id
FROM track_intervals i
JOIN campaigns c ON c.id = i.campaign_id;
)sql";

// SQLite cannot alter a CHECK constraint. Its documented way for a constraint change that leaves
// every stored row as it is (sqlite.org/lang_altertable.html, "writable_schema"): rewrite the
// table's SQL in the schema and bump the schema cookie, so that every connection reloads it.
void AllowTrackJobs(Database& db) {
  const std::string before = "CHECK (kind IN ('train', 'position', 'eval'))";
  const std::string after = "CHECK (kind IN ('train', 'position', 'eval', 'track'))";
  Statement cookie = db.Prepare("PRAGMA schema_version");
  cookie.Step();
  const std::int64_t version = cookie.Int(cookie.Column("schema_version"));
  cookie.Reset();
  db.Exec("PRAGMA writable_schema = ON");
  Statement rewrite = db.Prepare(
      "UPDATE sqlite_master SET sql = replace(sql, ?, ?) "
      "WHERE type = 'table' AND name = 'jobs' AND instr(sql, ?) > 0");
  rewrite.Bind(before).Bind(after).Bind(before).Run();
  const int rewritten = db.Changes();
  db.Exec("PRAGMA schema_version = " + std::to_string(version + 1));
  db.Exec("PRAGMA writable_schema = OFF");
  if (rewritten != 1)
    throw StoreError(db.file(), "table jobs has no kind constraint to extend: " + before);
}

const std::vector<Migration>& Migrations() {
  static const std::vector<Migration> migrations = [] {
    std::vector<Migration> out{{1, kVersion1, nullptr, nullptr},
                               {2, kVersion2, nullptr, nullptr},
                               {3, kVersion3, ConvertArgvColumns, kVersion3After},
                               {4, kVersion4, nullptr, nullptr},
                               {5, kVersion5, nullptr, nullptr},
                               {6, kVersion6, nullptr, nullptr},
                               {7, kVersion7, nullptr, nullptr},
                               {8, kVersion8, nullptr, nullptr},
                               {9, kVersion9, nullptr, nullptr},
                               {10, kVersion10, nullptr, nullptr}};
    // The columns of the eval metrics declared after version 10 (store/metric_columns.h).
    for (auto& migration : DerivedMetricMigrations())
      out.push_back(std::move(migration));
    out.push_back({12, kVersion12, nullptr, nullptr});
    out.push_back({13, kVersion13, AllowTrackJobs, nullptr});
    std::stable_sort(out.begin(), out.end(),
                     [](const Migration& a, const Migration& b) { return a.version < b.version; });
    return out;
  }();
  return migrations;
}

int LatestSchemaVersion() {
  return Migrations().back().version;
}

int ReadSchemaVersion(Database& db) {
  Statement has_version =
      db.Prepare("SELECT COUNT(*) AS n FROM sqlite_master WHERE type = 'table' AND name = ?");
  has_version.Bind("schema_version");
  has_version.Step();
  if (has_version.Int(has_version.Column("n")) == 0) {
    Statement tables = db.Prepare("SELECT COUNT(*) AS n FROM sqlite_master");
    tables.Step();
    if (tables.Int(tables.Column("n")) > 0) {
      throw StoreError(db.file(),
                       "is an SQLite database but not an RLpos results store (no schema_version "
                       "table)");
    }
    return 0;
  }
  Statement version = db.Prepare("SELECT version FROM schema_version");
  if (!version.Step())
    throw StoreError(db.file(), "schema_version table is empty");
  const auto v = version.Int(version.Column("version"));
  if (version.Step())
    throw StoreError(db.file(), "schema_version table has several rows");
  return static_cast<int>(v);
}

void MigrateSchema(Database& db) {
  const int latest = LatestSchemaVersion();
  const auto check = [&](int version) {
    if (version > latest) {
      throw StoreError(db.file(), "schema version " + std::to_string(version) +
                                      " is newer than this build knows (" + std::to_string(latest) +
                                      "); use a newer rlpos");
    }
  };
  int version = ReadSchemaVersion(db);
  check(version);
  if (version == latest)
    return;
  if (db.read_only()) {
    throw StoreError(db.file(), "schema version " + std::to_string(version) +
                                    " needs migrating to " + std::to_string(latest) +
                                    "; open it read-write once");
  }
  for (const auto& migration : Migrations()) {
    Transaction transaction(db);
    // Re-read under the write lock: another process may have migrated meanwhile.
    version = ReadSchemaVersion(db);
    check(version);
    if (migration.version <= version)
      continue;
    db.Exec(migration.sql);
    if (migration.convert)
      migration.convert(db);
    if (migration.sql_after)
      db.Exec(migration.sql_after);
    if (version == 0) {
      db.Exec("CREATE TABLE schema_version (version INTEGER NOT NULL)");
      db.Prepare("INSERT INTO schema_version (version) VALUES (?)").Bind(migration.version).Run();
    } else {
      db.Prepare("UPDATE schema_version SET version = ?").Bind(migration.version).Run();
    }
    transaction.Commit();
  }
}

}  // namespace rlpos
