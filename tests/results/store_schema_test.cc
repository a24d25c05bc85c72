// The results store's file handling: schema creation and migration, and every way opening a
// file can fail, each with an error that names the file.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "store/results_store.h"
#include "store/schema.h"
#include "store/store_error.h"
#include "test_support.h"

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
    ResultsStore store(file, options);
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
    ResultsStore store(file);
    EXPECT_EQ(store.SchemaVersion(), LatestSchemaVersion());
    EXPECT_EQ(store.file(), file);
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  sqlite3_prepare_v2(db, "PRAGMA journal_mode", -1, &stmt, nullptr);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0)), "wal");
  sqlite3_finalize(stmt);
  sqlite3_prepare_v2(db,
                     "SELECT COUNT(*) FROM sqlite_master WHERE name IN ('campaigns', 'jobs', "
                     "'metrics', 'artifacts', 'schema_version', 'v_eval_runs', "
                     "'v_campaign_progress', 'workers')",
                     -1, &stmt, nullptr);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(stmt, 0), 8);
  sqlite3_finalize(stmt);
  sqlite3_close(db);
}

TEST(StoreSchema, EmptyFileIsMigrated) {
  TempDir dir;
  const std::string file = dir.File("empty.db");
  WriteFile(file, "");
  ResultsStore store(file);
  EXPECT_EQ(store.SchemaVersion(), LatestSchemaVersion());
  EXPECT_TRUE(store.AllProgress().empty());
}

TEST(StoreSchema, ReopeningKeepsEverything) {
  TempDir dir;
  const std::string file = dir.File("keep.db");
  const ExpandedCampaign campaign = testing::MiniCampaign();
  ResultsStore(file).Submit(campaign);
  ResultsStore again(file);
  EXPECT_EQ(again.Progress(campaign.id).total, 44);
  EXPECT_FALSE(again.Submit(campaign).created);
  StoreOptions read_only;
  read_only.read_only = true;
  ResultsStore reader(file, read_only);
  EXPECT_EQ(reader.Progress(campaign.id).ready, 8);
}

TEST(StoreSchema, NewerVersionIsRefused) {
  TempDir dir;
  const std::string file = dir.File("future.db");
  ResultsStore{file};
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
  ResultsStore{file};
  StoreOptions options;
  options.read_only = true;
  ResultsStore reader(file, options);
  try {
    reader.Submit(testing::MiniCampaign());
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
  ResultsStore{file};
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

TEST(StoreSchema, ReadOnlyFile) {
  if (geteuid() == 0)
    GTEST_SKIP() << "root writes to read-only files";
  TempDir dir;
  const std::string file = dir.File("locked.db");
  ResultsStore{file};
  ASSERT_EQ(chmod(file.c_str(), 0444), 0);
  EXPECT_EQ(OpenError(file), "results store " + file +
                                 ": the file is read-only; the results store needs write "
                                 "access");
}

}  // namespace
}  // namespace rlpos
