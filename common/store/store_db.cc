#include "common/store/store_db.h"

#include <chrono>

#include "common/store/schema.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_error.h"

namespace rlpos {
namespace {

double SystemNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

StoreBatch::StoreBatch(std::unique_ptr<Transaction> transaction)
    : transaction_(std::move(transaction)) {}
StoreBatch::~StoreBatch() = default;
StoreBatch::StoreBatch(StoreBatch&&) noexcept = default;
void StoreBatch::Commit() {
  transaction_->Commit();
}

StoreDb::StoreDb(const std::string& file, StoreOptions options) : options_(std::move(options)) {
  if (!options_.clock)
    options_.clock = SystemNow;
  db_ = std::make_unique<Database>(file, options_.read_only, options_.busy_timeout_ms);
  if (!options_.read_only) {
    // WAL: readers (status, report) never block the coordinator's writes, nor it them.
    Statement mode = db_->Prepare("PRAGMA journal_mode = WAL");
    if (!mode.Step() || mode.Text(mode.Column("journal_mode")) != "wal") {
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

StoreDb::~StoreDb() = default;

const std::string& StoreDb::file() const {
  return db_->file();
}

int StoreDb::SchemaVersion() {
  return ReadSchemaVersion(*db_);
}

StoreBatch StoreDb::Batch() {
  return StoreBatch(std::make_unique<Transaction>(*db_));
}

void StoreDb::RequireCampaign(const std::string& campaign_id) {
  Statement select = db_->Prepare("SELECT 1 FROM campaigns WHERE id = ?");
  select.Bind(campaign_id);
  if (!select.Step())
    throw StoreError(file(), "no campaign \"" + campaign_id + "\"");
}

}  // namespace rlpos
