// The results store's file handling: schema creation and migration, and every way opening a
// file can fail, each with an error that names the file.
#include <grp.h>
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/job/position_rule.h"
#include "common/scenario/number_text.h"
#include "common/store/schema.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"
#include "common/wire/job_order.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using testing::TempDir;
using testing::WriteFile;

// Runs constant SQL on a file with the plain C API, as another tool would.
void Sql(const std::string& file, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
  EXPECT_EQ(rc, SQLITE_OK) << (error ? error : "");
  sqlite3_free(error);
  sqlite3_close(db);
}

// The StoreError message of opening `file`, or "" when it opened.
std::string OpenError(const std::string& file, bool read_only = false) {
  try {
    StoreOptions options;
    options.read_only = read_only;
    CoordinatorStore store(file, options);
  } catch (const StoreError& e) {
    EXPECT_EQ(e.file(), file);
    return e.what();
  }
  return "";
}

TEST(StoreSchema, MigrationsAreNumberedInOrder) {
  const auto& migrations = Migrations();
  ASSERT_FALSE(migrations.empty());
  for (std::size_t i = 0; i < migrations.size(); ++i) {
    EXPECT_EQ(migrations[i].version, static_cast<int>(i + 1));
  }
  EXPECT_EQ(LatestSchemaVersion(), migrations.back().version);
}

TEST(StoreSchema, NewFileGetsTheLatestSchemaInWalMode) {
  TempDir dir;
  const std::string file = dir.File("new.db");
  {
    CoordinatorStore store(file);
    EXPECT_EQ(store.db.SchemaVersion(), LatestSchemaVersion());
    EXPECT_EQ(store.db.file(), file);
  }
  Database db(file, /*read_only=*/false, /*busy_timeout_ms=*/0);
  Statement mode = db.Prepare("PRAGMA journal_mode");
  ASSERT_TRUE(mode.Step());
  EXPECT_EQ(mode.Text(mode.Column("journal_mode")), "wal");
  Statement tables = db.Prepare(
      "SELECT COUNT(*) AS n FROM sqlite_master WHERE name IN ('campaigns', 'jobs', "
      "'metrics', 'artifacts', 'schema_version', 'v_eval_runs', "
      "'v_campaign_progress', 'workers')");
  ASSERT_TRUE(tables.Step());
  EXPECT_EQ(tables.Int(tables.Column("n")), 8);
}

TEST(StoreSchema, EmptyFileIsMigrated) {
  TempDir dir;
  const std::string file = dir.File("empty.db");
  WriteFile(file, "");
  CoordinatorStore store(file);
  EXPECT_EQ(store.db.SchemaVersion(), LatestSchemaVersion());
  EXPECT_TRUE(store.reader.AllProgress().empty());
}

TEST(StoreSchema, ReopeningKeepsEverything) {
  TempDir dir;
  const std::string file = dir.File("keep.db");
  const ExpandedCampaign campaign = testing::MiniCampaign();
  CoordinatorStore(file).ledger.Submit(campaign);
  CoordinatorStore again(file);
  EXPECT_EQ(again.reader.Progress(campaign.id).total, 44);
  EXPECT_FALSE(again.ledger.Submit(campaign).created);
  StoreOptions read_only;
  read_only.read_only = true;
  CoordinatorStore reader(file, read_only);
  EXPECT_EQ(reader.reader.Progress(campaign.id).ready, 8);
}

TEST(StoreSchema, NewerVersionIsRefused) {
  TempDir dir;
  const std::string file = dir.File("future.db");
  StoreDb{file};
  Sql(file, "UPDATE schema_version SET version = 99");
  const std::string error = OpenError(file);
  EXPECT_EQ(error, "results store " + file +
                       ": schema version 99 is newer than this build knows (" +
                       std::to_string(LatestSchemaVersion()) + "); use a newer rlpos");
  EXPECT_NE(OpenError(file, true).find("schema version 99 is newer"), std::string::npos);
}

TEST(StoreSchema, ReadOnlyOpenDoesNotMigrate) {
  TempDir dir;
  const std::string file = dir.File("old.db");
  WriteFile(file, "");
  EXPECT_NE(OpenError(file, true).find("schema version 0 needs migrating to"), std::string::npos);
  EXPECT_NE(OpenError(dir.File("missing.db"), true).find("cannot open"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir.File("missing.db")));
}

TEST(StoreSchema, ReadOnlyStoreRefusesWrites) {
  TempDir dir;
  const std::string file = dir.File("ro.db");
  StoreDb{file};
  StoreOptions options;
  options.read_only = true;
  CoordinatorStore reader(file, options);
  try {
    reader.ledger.Submit(testing::MiniCampaign());
    FAIL() << "no error";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("readonly"), std::string::npos) << e.what();
  }
}

TEST(StoreSchema, BadPath) {
  const std::string error = OpenError("/nonexistent-rlpos-dir/sub/rlpos.db");
  EXPECT_EQ(error.rfind("results store /nonexistent-rlpos-dir/sub/rlpos.db: cannot open", 0), 0u)
      << error;
  TempDir dir;
  EXPECT_NE(OpenError(dir.path()).find("results store " + dir.path() + ": "), std::string::npos);
}

TEST(StoreSchema, NotADatabase) {
  TempDir dir;
  const std::string file = dir.File("notes.txt");
  WriteFile(file, std::string(4096, 'x'));
  const std::string error = OpenError(file);
  EXPECT_NE(error.find("results store " + file + ": file is not a database"), std::string::npos)
      << error;
}

TEST(StoreSchema, CorruptDatabase) {
  TempDir dir;
  const std::string file = dir.File("corrupt.db");
  StoreDb{file};
  {
    // Overwrite the schema page's b-tree header and cells, keeping the 100-byte file header.
    std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
    io.seekp(100);
    const std::string garbage(3000, '\xA5');
    io.write(garbage.data(), static_cast<std::streamsize>(garbage.size()));
  }
  const std::string error = OpenError(file);
  EXPECT_NE(error.find("results store " + file + ": "), std::string::npos) << error;
  EXPECT_NE(error.find("malformed"), std::string::npos) << error;
}

TEST(StoreSchema, ForeignSqliteDatabase) {
  TempDir dir;
  const std::string file = dir.File("other.db");
  Sql(file, "CREATE TABLE things (x INTEGER)");
  EXPECT_EQ(OpenError(file), "results store " + file +
                                 ": is an SQLite database but not an RLpos results store (no "
                                 "schema_version table)");
}

// What opening `file` read-write says ("" when it opened), tried by a user that write
// permissions apply to. Root writes to a read-only file, so as root the open runs in a child
// process that first becomes the unprivileged user 65534, which then owns `dir` and `file` (as
// the test's user does otherwise). Sets `skip` when root cannot drop its privileges here.
std::string OpenErrorWithoutPrivileges(const std::string& dir, const std::string& file,
                                       std::string& skip) {
  if (geteuid() != 0)
    return OpenError(file);
  constexpr uid_t kNobody = 65534;
  if (chown(dir.c_str(), kNobody, kNobody) != 0 || chown(file.c_str(), kNobody, kNobody) != 0) {
    skip = std::string("cannot hand the test folder to uid 65534: ") + std::strerror(errno);
    return "";
  }
  int fds[2];
  if (pipe(fds) != 0) {
    skip = std::string("pipe: ") + std::strerror(errno);
    return "";
  }
  const pid_t pid = fork();
  if (pid == 0) {
    // The child: no gtest, no exit handlers; the answer goes through the pipe.
    close(fds[0]);
    std::string answer;
    int code = 0;
    if (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) {
      answer = std::string("cannot drop root privileges: ") + std::strerror(errno);
      code = 3;
    } else {
      try {
        CoordinatorStore store(file);
      } catch (const StoreError& e) {
        answer = e.what();
      } catch (const std::exception& e) {
        answer = std::string("unexpected exception: ") + e.what();
      }
    }
    const ssize_t written = write(fds[1], answer.data(), answer.size());
    _exit(written == static_cast<ssize_t>(answer.size()) ? code : 4);
  }
  close(fds[1]);
  std::string answer;
  char buffer[512];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
    answer.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) {
    ADD_FAILURE() << "the unprivileged child did not end normally";
    return "";
  }
  if (WEXITSTATUS(status) == 3)
    skip = answer;
  else
    EXPECT_EQ(WEXITSTATUS(status), 0) << answer;
  return answer;
}

TEST(StoreSchema, ReadOnlyFile) {
  TempDir dir;
  const std::string file = dir.File("locked.db");
  StoreDb{file};
  ASSERT_EQ(chmod(file.c_str(), 0444), 0);
  std::string skip;
  const std::string error = OpenErrorWithoutPrivileges(dir.path(), file, skip);
  if (!skip.empty())
    GTEST_SKIP() << "running as root, and " << skip;
  EXPECT_EQ(error, "results store " + file +
                       ": the file is read-only; the results store needs write access");
}

// A schema-2 file as the previous release left it: the v1 and v2 DDL, version 2, and jobs
// stored as rlpos-sim command lines (argv_json) the way that release's expansion wrote them.
class LegacyStoreTest : public ::testing::Test {
 protected:
  LegacyStoreTest() : file_(dir_.File("v2.db")) {}

  void SetUp() override {
    const auto& migrations = Migrations();
    ASSERT_GE(migrations.size(), 3u);
    Sql(file_, std::string(migrations[0].sql) + migrations[1].sql +
                   "CREATE TABLE schema_version (version INTEGER NOT NULL);"
                   "INSERT INTO schema_version (version) VALUES (2);"
                   "INSERT INTO campaigns VALUES ('c0ffee', 'old', '{}', 1000, 'active', 2, 300);");
  }

  // Inserts one job row of campaign c0ffee; `seq` orders ListReady.
  void InsertJob(int seq, const std::string& kind, const std::string& key, const std::string& label,
                 const std::string& rng_run, const std::string& train_seed,
                 const std::string& depends_on, const std::string& state,
                 const nlohmann::json& argv, const PositionRule& rule = {},
                 const std::string& result_json = "NULL") {
    const auto quoted = [](const std::string& text) {
      std::string out = "'";
      for (char c : text)
        out += c == '\'' ? std::string("''") : std::string(1, c);
      return out + "'";
    };
    Sql(file_,
        "INSERT INTO jobs (id, campaign_id, seq, kind, key, scenario, label, rng_run, train_seed, "
        "depends_on, state, attempt, max_attempts, timeout_s, created_at, argv_json, "
        "position_rule_json, result_json) VALUES (" +
            quoted("c0ffee/" + key) + ", 'c0ffee', " + std::to_string(seq) + ", " + quoted(kind) +
            ", " + quoted(key) + ", 'B', " + quoted(label) + ", " + rng_run + ", " + train_seed +
            ", " + (depends_on.empty() ? std::string("NULL") : quoted("c0ffee/" + depends_on)) +
            ", " + quoted(state) + ", 1, 2, 300, 1000, " + quoted(argv.dump()) + ", " +
            quoted(ToJson(rule).dump()) + ", " + result_json + ")");
  }

  // The old expansion's rows: a finished train job, a ready position job, an eval whose
  // position the train job bound, and an eval still waiting for the position job.
  void InsertOldCampaign() {
    InsertJob(
        0, "train", "train/B/seed1", "rl", "NULL", "1", "", "succeeded",
        {"rlpos-sim", "train", "--scenario", "/x/b.json", "--seed", "1", "--fidelity", "packet",
         "--out", "{out_dir}", "--json", "--set", "agent.train_episodes=25", "--set",
         "simulation.duration=5", "--set", "simulation.warmup=0.5", "--set", "wifi.mode=adhoc"},
        {}, "'{\"position\": [50, 35.5, 10]}'");
    InsertJob(1, "position", "position/B/oracle", "oracle", "NULL", "NULL", "", "ready",
              {"rlpos-sim", "position", "--scenario", "/x/b.json", "--positioner", "oracle",
               "--json", "--set", "simulation.duration=5", "--set", "simulation.warmup=0.5",
               "--set", "wifi.mode=adhoc"});
    InsertJob(2, "eval", "eval/B/rl/run2", "rl", "2", "1", "train/B/seed1", "ready",
              {"rlpos-sim", "eval", "--scenario", "/x/b.json", "--position", "50,35.5,10", "--run",
               "2", "--duration", "5", "--json", "--no-progress", "--set", "simulation.warmup=0.5",
               "--set", "wifi.mode=adhoc"});
    InsertJob(3, "eval", "eval/B/oracle/run1", "oracle", "1", "NULL", "position/B/oracle",
              "pending",
              {"rlpos-sim", "eval", "--scenario", "/x/b.json", "--position", "{position}", "--run",
               "1", "--duration", "5", "--json", "--no-progress", "--set", "simulation.warmup=0.5",
               "--set", "wifi.mode=adhoc"});
  }

  // One value through the C API, "<null>" for NULL.
  std::string Query(const std::string& sql) { return testing::QueryOne(file_, sql); }
  std::string Column(const std::string& column, const std::string& key) {
    return Query("SELECT " + column + " FROM jobs WHERE key = '" + key + "'");
  }

  TempDir dir_;
  std::string file_;
};

TEST_F(LegacyStoreTest, ArgvBecomesTypedColumnsAndIsDropped) {
  InsertOldCampaign();
  CoordinatorStore store(file_);
  EXPECT_EQ(store.db.SchemaVersion(), LatestSchemaVersion());
  EXPECT_EQ(Query("SELECT COUNT(*) FROM pragma_table_info('jobs') WHERE name = 'argv_json'"), "0");

  const std::string eval = "eval/B/rl/run2";
  EXPECT_EQ(Column("duration_s", eval), "5.0");
  EXPECT_EQ(Column("overrides_json", eval),
            R"([["simulation.warmup","0.5"],["wifi.mode","adhoc"]])");
  EXPECT_EQ(Column("x || ',' || y || ',' || z", eval), "50.0,35.5,10.0");
  EXPECT_EQ(Column("fidelity", eval), "<null>");
  EXPECT_EQ(Column("positioner", eval), "<null>");
  EXPECT_EQ(Column("rng_run", eval), "2");

  const std::string train = "train/B/seed1";
  EXPECT_EQ(Column("fidelity", train), "packet");
  EXPECT_EQ(Column("overrides_json", train),
            R"([["agent.train_episodes","25"],["simulation.duration","5"],)"
            R"(["simulation.warmup","0.5"],["wifi.mode","adhoc"]])");
  EXPECT_EQ(Column("x", train), "<null>");

  EXPECT_EQ(Column("positioner", "position/B/oracle"), "oracle");
  EXPECT_EQ(Column("duration_s", "position/B/oracle"), "<null>");  // it was a --set
  // The "{position}" placeholder is no position.
  EXPECT_EQ(Column("x", "eval/B/oracle/run1"), "<null>");
  EXPECT_EQ(Column("duration_s", "eval/B/oracle/run1"), "5.0");
}

TEST_F(LegacyStoreTest, MigratedJobsReadAndRunAsTheyWould) {
  InsertOldCampaign();
  CoordinatorStore store(file_);
  const std::vector<ScenarioOverride> eval_set{{"simulation.warmup", "0.5"},
                                               {"wifi.mode", "adhoc"}};
  const auto ready = store.ledger.ListReady();
  ASSERT_EQ(ready.size(), 2u);
  EXPECT_EQ(ready[0].id, "c0ffee/position/B/oracle");
  EXPECT_EQ(ready[0].params.kind, JobKind::kPosition);
  EXPECT_EQ(ready[0].params.positioner, "oracle");
  EXPECT_FALSE(ready[0].placement.has_value());
  EXPECT_EQ(ready[1].id, "c0ffee/eval/B/rl/run2");
  const JobParams& p = ready[1].params;
  EXPECT_EQ(p.kind, JobKind::kEval);
  EXPECT_EQ(p.scenario, "B");
  EXPECT_EQ(p.rng_run, 2u);
  EXPECT_EQ(p.train_seed, 1u);
  EXPECT_EQ(p.duration_s, 5.0);
  EXPECT_FALSE(p.warmup_s.has_value());  // the old --set, now an override
  EXPECT_EQ(p.overrides, eval_set);
  EXPECT_EQ(testing::FormatPlacement(ready[1].placement), "50,35.5,10");
  EXPECT_DOUBLE_EQ(ready[1].timeout_s, 300.0);

  const auto train = store.reader.GetJob("c0ffee/train/B/seed1");
  ASSERT_TRUE(train.has_value());
  EXPECT_EQ(train->state, "succeeded");
  EXPECT_EQ(train->params.kind, JobKind::kTrain);
  EXPECT_EQ(train->params.fidelity, "packet");
  EXPECT_EQ(train->params.train_seed, 1u);
  ASSERT_EQ(train->params.overrides.size(), 4u);
  EXPECT_EQ(train->params.overrides[0], (ScenarioOverride{"agent.train_episodes", "25"}));
  EXPECT_EQ(train->result->at("position")[1], 35.5);

  // The scenario a migrated eval runs is the one its command line described.
  const nlohmann::json scenario = EffectiveScenarioDocument(
      nlohmann::json::parse(testing::ReadFile(testing::SourcePath("campaigns/scenarios/b.json"))),
      p);
  EXPECT_EQ(scenario["simulation"]["duration"], 5);
  EXPECT_EQ(scenario["simulation"]["run"], 2);
  EXPECT_EQ(scenario["simulation"]["warmup"], 0.5);
  EXPECT_EQ(scenario["wifi"]["mode"], "adhoc");

  // The waiting eval is bound when its position job succeeds, like any schema-3 job.
  const auto waiting = store.reader.GetJob("c0ffee/eval/B/oracle/run1");
  ASSERT_TRUE(waiting.has_value());
  EXPECT_EQ(waiting->state, "pending");
  EXPECT_FALSE(waiting->placement.has_value());
  ASSERT_TRUE(store.ledger.MarkRunning("c0ffee/position/B/oracle", "w1", 0, 1));
  ASSERT_EQ(store.recorder.RecordSuccess("c0ffee/position/B/oracle", 1,
                                         testing::PositionResult(20, 30, 15)),
            JobUpdate::kSucceeded);
  const auto bound = store.reader.GetJob("c0ffee/eval/B/oracle/run1");
  EXPECT_EQ(bound->state, "ready");
  EXPECT_EQ(testing::FormatPlacement(bound->placement), "20,30,15");
}

TEST_F(LegacyStoreTest, UnreadableArgvLeavesTheFileAtVersionTwo) {
  InsertOldCampaign();
  InsertJob(4, "eval", "eval/B/rl/run3", "rl", "3", "1", "train/B/seed1", "ready",
            {"rlpos-sim", "eval", "--set", "no-equals-sign"});
  try {
    CoordinatorStore store(file_);
    FAIL() << "migrated";
  } catch (const StoreError& e) {
    EXPECT_EQ(e.file(), file_);
    EXPECT_NE(std::string(e.what()).find("job c0ffee/eval/B/rl/run3: cannot read argv_json"),
              std::string::npos)
        << e.what();
  }
  // Nothing of the migration stayed: the old release can still open it.
  EXPECT_EQ(Query("SELECT version FROM schema_version"), "2");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM pragma_table_info('jobs') WHERE name = 'argv_json'"), "1");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM pragma_table_info('jobs') WHERE name = 'fidelity'"), "0");
}

TEST_F(LegacyStoreTest, ReadOnlyOpenAsksForOneReadWriteOpen) {
  InsertOldCampaign();
  EXPECT_NE(OpenError(file_, true)
                .find("schema version 2 needs migrating to " +
                      std::to_string(LatestSchemaVersion()) + ""),
            std::string::npos);
  EXPECT_EQ(Query("SELECT version FROM schema_version"), "2");
}

}  // namespace
}  // namespace rlpos
