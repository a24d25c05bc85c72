#pragma once
// A results database for the campaign page's tests: the mini campaign (scenarios B and C, runs
// 1-2, every positioner) with some of its jobs done through the store as the coordinator does
// it: positions, one train job with its learning curve, evals of B (oracle and rl: an optimality
// row) and of C, one failed eval. The writer is closed afterwards, so the file's bytes
// are what a read-only server must leave alone.
#include <string>

#include "common/campaign/expansion.h"
#include "tests/support/temp_dir.h"

namespace rlpos::web::testing {

class CampaignDb {
 public:
  CampaignDb();
  const std::string& file() const { return file_; }
  const std::string& id() const { return campaign_.id; }
  // SHA-256 of the database file (and its -wal, when there is one).
  std::string Hash() const;
  // Runs SQL on the file with a writer of its own (to plant hostile rows).
  void Exec(const std::string& sql) const;

 private:
  rlpos::testing::TempDir dir_;
  std::string file_;
  ExpandedCampaign campaign_;
};

}  // namespace rlpos::web::testing
