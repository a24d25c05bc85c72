// Rows are read by column name: Statement::Column resolves a name once per statement, so that a
// SELECT whose columns are reordered (or a view that gains some) reads the same fields.
#include <gtest/gtest.h>

#include <string>

#include "common/store/job_rows.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

class StatementColumnsTest : public ::testing::Test {
 protected:
  StatementColumnsTest() : db_(dir_.File("c.db"), false, 1000) {
    db_.Exec("CREATE TABLE t (a INTEGER, b TEXT, c REAL)");
    db_.Exec("INSERT INTO t VALUES (7, 'seven', 0.5)");
  }
  testing::TempDir dir_;
  Database db_;
};

TEST_F(StatementColumnsTest, AReorderedSelectReadsTheSameFields) {
  for (const char* sql : {"SELECT a, b, c FROM t", "SELECT c, b, a FROM t",
                          "SELECT b, 'other' AS d, c, a FROM t", "SELECT t.c, t.a, t.b FROM t"}) {
    Statement select = db_.Prepare(sql);
    const ResultColumn a = select.Column("a"), b = select.Column("b"), c = select.Column("c");
    ASSERT_TRUE(select.Step()) << sql;
    EXPECT_EQ(select.Int(a), 7) << sql;
    EXPECT_EQ(select.Text(b), "seven") << sql;
    EXPECT_EQ(select.Double(c), 0.5) << sql;
  }
}

TEST_F(StatementColumnsTest, AnAsNameIsTheColumnsName) {
  Statement select = db_.Prepare("SELECT COUNT(*) AS n, MAX(a) AS top FROM t");
  ASSERT_TRUE(select.Step());
  EXPECT_EQ(select.Int(select.Column("n")), 1);
  EXPECT_EQ(select.Int(select.Column("top")), 7);
}

TEST_F(StatementColumnsTest, AMissingOrAmbiguousNameThrows) {
  Statement select = db_.Prepare("SELECT a, b AS a, c FROM t");
  try {
    select.Column("z");
    ADD_FAILURE() << "no exception";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("no result column named \"z\""), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(select.Column("a"), StoreError);
  EXPECT_NO_THROW(select.Column("c"));
}

// The store's job columns (kParamColumns), read from a SELECT of another order: every field
// comes back from its own column.
TEST_F(StatementColumnsTest, JobParamsFromAReorderedSelect) {
  db_.Exec(
      "CREATE TABLE jobs (kind TEXT, scenario TEXT, train_seed INTEGER, fidelity TEXT, "
      "train_episodes INTEGER, positioner TEXT, rng_run INTEGER, duration_s REAL, warmup_s REAL, "
      "overrides_json TEXT, x REAL, y REAL, z REAL, positions_json TEXT, policy_sha256 TEXT)");
  db_.Exec(
      "INSERT INTO jobs VALUES ('eval', 'B', 11, 'packet', 12, 'oracle', 13, 14.5, 15.5, "
      "'[[\"wifi.width\", \"40\"]]', 1, 2, 3, NULL, 'abc')");
  const auto read = [this](const std::string& columns) {
    Statement select = db_.Prepare("SELECT " + columns + " FROM jobs");
    const ParamColumns c(select);
    EXPECT_TRUE(select.Step());
    std::optional<Placement> placement;
    const JobParams p = ReadParams(select, c, placement, db_.file());
    EXPECT_EQ(p.kind, JobKind::kEval);
    EXPECT_EQ(p.scenario, "B");
    EXPECT_EQ(p.train_seed, 11u);
    EXPECT_EQ(p.fidelity, "packet");
    EXPECT_EQ(p.train_episodes, 12);
    EXPECT_EQ(p.positioner, "oracle");
    EXPECT_EQ(p.rng_run, 13u);
    EXPECT_EQ(p.duration_s, 14.5);
    EXPECT_EQ(p.warmup_s, 15.5);
    ASSERT_EQ(p.overrides.size(), 1u);
    EXPECT_EQ(p.overrides[0].path, "wifi.width");
    EXPECT_EQ(p.overrides[0].value, "40");
    EXPECT_EQ(p.policy_sha256, "abc");
    ASSERT_TRUE(placement.has_value());
    ASSERT_EQ(placement->size(), 1u);
    EXPECT_EQ(placement->front().x, 1);
    EXPECT_EQ(placement->front().y, 2);
    EXPECT_EQ(placement->front().z, 3);
  };
  read(kParamColumns);
  read(
      "policy_sha256, z, y, x, positions_json, warmup_s, duration_s, rng_run, positioner, "
      "train_episodes, fidelity, train_seed, scenario, kind, overrides_json, 0 AS extra");
}

}  // namespace
}  // namespace rlpos
