// Schema 13: track jobs. A store of schema 12 migrates with its rows as they were, its jobs may
// then be 'track' (SQLite cannot alter the CHECK that said otherwise: the migration rewrites
// it), and every track metric has its column.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/metrics/track_metrics.h"
#include "common/store/schema.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"
#include "tests/support/store_migrations.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

// The store as schema `version` left it, its version recorded.
void MigrateTo(Database& db, int version) {
  testing::MigrateUpTo(db, version);
  db.Exec("CREATE TABLE schema_version (version INTEGER NOT NULL)");
  db.Exec("INSERT INTO schema_version (version) VALUES (" + std::to_string(version) + ")");
}

std::string InsertJob(const std::string& id, const std::string& kind) {
  return "INSERT INTO jobs (id, campaign_id, seq, kind, key, scenario, label, state, attempt, "
         "max_attempts, timeout_s, created_at, position_rule_json) VALUES ('" +
         id + "', 'c0ffee', 1, '" + kind + "', '" + id +
         "', 'B', 'x', 'ready', 1, 2, 300, 1000, '{}')";
}

// The first row's `column` of `sql`.
std::string Text(Database& db, const std::string& sql, const char* column) {
  Statement s = db.Prepare(sql);
  return s.Step() ? s.Text(s.Column(column)) : "";
}

TEST(TrackSchema, AStoreOfSchema12TakesTrackJobsAndKeepsItsRows) {
  testing::TempDir dir;
  const std::string file = dir.File("v12.db");
  {
    Database db(file, false, 1000);
    MigrateTo(db, 12);
    db.Exec(
        "INSERT INTO campaigns (id, name, spec_json, created_at, state, max_attempts, "
        "job_timeout_s) VALUES ('c0ffee', 'old', '{}', 1000, 'active', 2, 300)");
    db.Exec(InsertJob("c0ffee/eval", "eval"));
    EXPECT_THROW(db.Exec(InsertJob("c0ffee/early", "track")), StoreError) << "schema 12";
  }
  Database db(file, false, 1000);
  db.Exec("PRAGMA foreign_keys = ON");
  MigrateSchema(db);
  EXPECT_EQ(Text(db, "SELECT version FROM schema_version", "version"),
            std::to_string(LatestSchemaVersion()));
  EXPECT_EQ(Text(db, "SELECT kind FROM jobs WHERE id = 'c0ffee/eval'", "kind"), "eval");
  db.Exec(InsertJob("c0ffee/track", "track"));
  EXPECT_THROW(db.Exec(InsertJob("c0ffee/bogus", "bogus")), StoreError);
  EXPECT_EQ(Text(db, "PRAGMA integrity_check", "integrity_check"), "ok");
  EXPECT_EQ(Text(db, "SELECT COUNT(*) AS n FROM pragma_foreign_key_check", "n"), "0");
  // Another connection sees the new constraint too.
  Database other(file, false, 1000);
  other.Exec(InsertJob("c0ffee/track2", "track"));
  EXPECT_THROW(other.Exec(InsertJob("c0ffee/bogus", "bogus")), StoreError);
}

TEST(TrackSchema, EveryTrackMetricHasItsColumnInTrackRuns) {
  testing::TempDir dir;
  Database db(dir.File("new.db"), false, 1000);
  MigrateSchema(db);
  for (const TrackMetricDef& m : kTrackMetrics) {
    Statement info =
        db.Prepare("SELECT type, \"notnull\" FROM pragma_table_info('track_runs') WHERE name = ?");
    info.Bind(m.key);
    ASSERT_TRUE(info.Step()) << m.key << " has no column in track_runs: add it in a migration";
    EXPECT_EQ(info.Text(info.Column("type")), "REAL") << m.key;
    EXPECT_EQ(info.Int(info.Column("notnull")), m.nullable ? 0 : 1) << m.key;
  }
}

}  // namespace
}  // namespace rlpos
