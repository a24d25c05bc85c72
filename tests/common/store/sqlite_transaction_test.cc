// Nested transactions of the store: the outermost is BEGIN ... COMMIT, inner ones savepoints
// that roll back alone; nothing reaches the file before the outermost commits.
#include <gtest/gtest.h>

#include <stdexcept>

#include "common/store/sqlite_db.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

class TransactionTest : public ::testing::Test {
 protected:
  TransactionTest() : db_(dir_.File("t.db"), false, 1000) {
    db_.Exec("CREATE TABLE t (v INTEGER)");
  }
  int Count(Database& db) {
    Statement count = db.Prepare("SELECT COUNT(*) AS n FROM t");
    count.Step();
    return static_cast<int>(count.Int(count.Column("n")));
  }
  void Insert(int v) { db_.Prepare("INSERT INTO t (v) VALUES (?)").Bind(v).Run(); }

  testing::TempDir dir_;
  Database db_;
};

TEST_F(TransactionTest, AnInnerRollbackKeepsTheOuterWork) {
  Transaction outer(db_);
  Insert(1);
  {
    Transaction inner(db_);
    Insert(2);
  }  // not committed: rolled back to its savepoint
  {
    Transaction inner(db_);
    Insert(3);
    inner.Commit();
  }
  outer.Commit();
  EXPECT_EQ(Count(db_), 2);
  Statement sum = db_.Prepare("SELECT SUM(v) AS total FROM t");
  sum.Step();
  EXPECT_EQ(sum.Int(sum.Column("total")), 4);
}

TEST_F(TransactionTest, NothingIsOnDiskBeforeTheOutermostCommits) {
  Database reader(dir_.File("t.db"), true, 1000);
  {
    Transaction outer(db_);
    {
      Transaction inner(db_);
      Insert(1);
      inner.Commit();
    }
    EXPECT_EQ(Count(reader), 0) << "a released savepoint is not a commit";
  }  // the outer rolls back, and takes the released inner work with it
  EXPECT_EQ(Count(db_), 0);
  {
    Transaction outer(db_);
    Insert(5);
    outer.Commit();
  }
  EXPECT_EQ(Count(reader), 1);
  // A new outermost transaction after nesting starts again with BEGIN.
  Transaction again(db_);
  Insert(6);
  again.Commit();
  EXPECT_EQ(Count(reader), 2);
}

}  // namespace
}  // namespace rlpos
