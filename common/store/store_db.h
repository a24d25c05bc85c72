#pragma once
// The results database that the store's classes share: one SQLite file (WAL mode, one writer:
// the coordinator), the source of truth of campaigns, jobs and their results, opened and
// migrated to the newest schema, with the clock that stamps its rows.
// The pieces over it, each one job:
//   JobLedger (store/job_ledger.h)          campaigns, job states, attempts, leases, workers
//   ResultRecorder (store/result_recorder.h) a job's result, provenance, metrics, artifacts
//   ResultCache (store/result_cache.h)       results served to jobs of the same content
//   ResultsReader (store/results_reader.h)   what status, results and reports read
// One StoreDb per thread (the connection is opened without SQLite's mutex); other processes
// may read the file at any time, and write it too, serialized by SQLite's locks.
#include <functional>
#include <memory>
#include <string>

namespace rlpos {

class Database;
class Transaction;

// Groups the store's writes into one SQLite transaction until Commit (rolled back if it goes
// out of scope first): one disk write for a whole scheduling round instead of one per job.
class StoreBatch {
 public:
  explicit StoreBatch(std::unique_ptr<Transaction> transaction);
  ~StoreBatch();
  StoreBatch(StoreBatch&&) noexcept;
  void Commit();

 private:
  std::unique_ptr<Transaction> transaction_;
};

struct StoreOptions {
  bool read_only = false;  // for readers (status, results, report): never writes, never migrates
  int busy_timeout_ms = 5000;
  std::function<double()> clock;  // seconds since the Unix epoch; default: the system clock
  // A job lost with its worker goes back to the queue without using its retries, up to this
  // many times; one more loss fails it.
  int max_infra_losses = 10;
};

class StoreDb {
 public:
  // Opens or creates the file and migrates it to the newest schema. Throws StoreError naming
  // the file (bad path, read-only file, not a database, corrupt, newer schema).
  explicit StoreDb(const std::string& file, StoreOptions options = {});
  ~StoreDb();
  StoreDb(const StoreDb&) = delete;
  StoreDb& operator=(const StoreDb&) = delete;

  const std::string& file() const;
  Database& sql() { return *db_; }
  const StoreOptions& options() const { return options_; }
  double Now() const { return options_.clock(); }
  int SchemaVersion();
  // Every write until the batch's Commit goes to disk as one transaction.
  StoreBatch Batch();
  // Throws StoreError for an unknown campaign.
  void RequireCampaign(const std::string& campaign_id);

 private:
  std::unique_ptr<Database> db_;
  StoreOptions options_;
};

}  // namespace rlpos
