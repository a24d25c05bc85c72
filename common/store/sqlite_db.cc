#include "common/store/sqlite_db.h"

#include <sqlite3.h>

#include <utility>

#include "common/store/store_error.h"

namespace rlpos {

Statement::Statement(sqlite3* db, sqlite3_stmt* compiled, const std::string& sql,
                     const std::string& file)
    : db_(db), stmt_(compiled), sql_(sql), file_(file) {}

Statement::Statement(sqlite3* db, const std::string& sql, const std::string& file)
    : db_(db), sql_(sql), file_(file) {
  const int rc = sqlite3_prepare_v2(db_, sql.c_str(), -1, &stmt_, nullptr);
  if (rc != SQLITE_OK)
    Fail(rc);
}

Statement::~Statement() {
  if (owner_ && stmt_)
    owner_->Release(sql_, stmt_);
  else
    sqlite3_finalize(stmt_);
}

Statement::Statement(Statement&& other) noexcept
    : owner_(std::exchange(other.owner_, nullptr)),
      db_(other.db_),
      stmt_(std::exchange(other.stmt_, nullptr)),
      sql_(std::move(other.sql_)),
      file_(std::move(other.file_)),
      next_(other.next_) {}

void Statement::Fail(int rc) const {
  std::string message = sqlite3_errmsg(db_);
  if (message.empty() || message == "not an error")
    message = sqlite3_errstr(rc);
  // The first line of the statement is enough to find it in the source.
  const std::string first_line = sql_.substr(0, sql_.find('\n'));
  throw StoreError(file_, message + " (in: " + first_line + ")");
}

Statement& Statement::Bind(const std::string& value) {
  const int rc = sqlite3_bind_text(stmt_, next_++, value.data(), static_cast<int>(value.size()),
                                   SQLITE_TRANSIENT);
  if (rc != SQLITE_OK)
    Fail(rc);
  return *this;
}

Statement& Statement::Bind(std::int64_t value) {
  const int rc = sqlite3_bind_int64(stmt_, next_++, value);
  if (rc != SQLITE_OK)
    Fail(rc);
  return *this;
}

Statement& Statement::Bind(std::uint64_t value) {
  // SQLite integers are signed 64-bit; RngRuns and seeds never come near 2^63.
  return Bind(static_cast<std::int64_t>(value));
}

Statement& Statement::Bind(double value) {
  const int rc = sqlite3_bind_double(stmt_, next_++, value);
  if (rc != SQLITE_OK)
    Fail(rc);
  return *this;
}

Statement& Statement::BindNull() {
  const int rc = sqlite3_bind_null(stmt_, next_++);
  if (rc != SQLITE_OK)
    Fail(rc);
  return *this;
}

bool Statement::Step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW)
    return true;
  if (rc == SQLITE_DONE)
    return false;
  Fail(rc);
}

void Statement::Run() {
  while (Step()) {
  }
}

void Statement::Reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
  next_ = 1;
}

ResultColumn Statement::Column(std::string_view name) const {
  int found = -1;
  const int count = sqlite3_column_count(stmt_);
  for (int i = 0; i < count; ++i) {
    const char* column = sqlite3_column_name(stmt_, i);
    if (column == nullptr || name != column)
      continue;
    if (found >= 0)
      throw StoreError(file_, "two result columns named \"" + std::string(name) +
                                  "\" (in: " + sql_.substr(0, sql_.find('\n')) + ")");
    found = i;
  }
  if (found < 0)
    throw StoreError(file_, "no result column named \"" + std::string(name) +
                                "\" (in: " + sql_.substr(0, sql_.find('\n')) + ")");
  return ResultColumn(found);
}

bool Statement::IsNull(ResultColumn column) const {
  return sqlite3_column_type(stmt_, column.index_) == SQLITE_NULL;
}

std::int64_t Statement::Int(ResultColumn column) const {
  return sqlite3_column_int64(stmt_, column.index_);
}

double Statement::Double(ResultColumn column) const {
  return sqlite3_column_double(stmt_, column.index_);
}

std::string Statement::Text(ResultColumn column) const {
  const auto* text = sqlite3_column_text(stmt_, column.index_);
  if (!text)
    return {};
  return std::string(reinterpret_cast<const char*>(text),
                     static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column.index_)));
}

std::optional<std::string> Statement::OptionalText(ResultColumn column) const {
  if (IsNull(column))
    return std::nullopt;
  return Text(column);
}

std::optional<std::int64_t> Statement::OptionalInt(ResultColumn column) const {
  if (IsNull(column))
    return std::nullopt;
  return Int(column);
}

std::optional<double> Statement::OptionalDouble(ResultColumn column) const {
  if (IsNull(column))
    return std::nullopt;
  return Double(column);
}

Database::Database(const std::string& file, bool read_only, int busy_timeout_ms)
    : file_(file), read_only_(read_only) {
  const int flags = read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  const int rc = sqlite3_open_v2(file.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(file, "cannot open: " + message);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, busy_timeout_ms);
  // SQLite silently falls back to read-only on a write-protected file; the store would then
  // fail on its first write with a less helpful message.
  if (!read_only && sqlite3_db_readonly(db_, "main") == 1) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(file, "the file is read-only; the results store needs write access");
  }
}

Database::~Database() {
  for (auto& [sql, statements] : idle_) {
    for (sqlite3_stmt* stmt : statements)
      sqlite3_finalize(stmt);
  }
  sqlite3_close(db_);
}

void Database::Release(const std::string& sql, sqlite3_stmt* stmt) {
  // A few per text: enough for the statements one operation holds at once.
  auto& statements = idle_[sql];
  if (statements.size() >= 4) {
    sqlite3_finalize(stmt);
    return;
  }
  sqlite3_reset(stmt);
  sqlite3_clear_bindings(stmt);
  statements.push_back(stmt);
}

void Database::Exec(const std::string& sql) {
  char* error = nullptr;
  const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error);
  if (rc != SQLITE_OK) {
    const std::string message = error ? error : sqlite3_errstr(rc);
    sqlite3_free(error);
    throw StoreError(file_, message);
  }
}

Statement Database::Prepare(const std::string& sql) {
  if (const auto it = idle_.find(sql); it != idle_.end() && !it->second.empty()) {
    Statement statement(db_, it->second.back(), sql, file_);
    it->second.pop_back();
    statement.owner_ = this;
    return statement;
  }
  Statement statement(db_, sql, file_);
  statement.owner_ = this;
  return statement;
}

int Database::Changes() const {
  return sqlite3_changes(db_);
}

// BEGIN, COMMIT, SAVEPOINT and RELEASE go through the statement cache: the coordinator opens
// one or more per job, and sqlite3_exec would parse each every time.
Transaction::Transaction(Database& db) : db_(db), depth_(db.transaction_depth_) {
  db_.Prepare(depth_ == 0 ? std::string("BEGIN IMMEDIATE")
                          : "SAVEPOINT rlpos_" + std::to_string(depth_))
      .Run();
  ++db_.transaction_depth_;
}

Transaction::~Transaction() {
  if (done_)
    return;
  --db_.transaction_depth_;
  try {
    if (depth_ == 0) {
      db_.Exec("ROLLBACK");
    } else {
      const std::string name = "rlpos_" + std::to_string(depth_);
      db_.Exec("ROLLBACK TO " + name);
      db_.Exec("RELEASE " + name);
    }
  } catch (const StoreError&) {
    // Already rolled back by SQLite (e.g. after SQLITE_FULL); nothing left to undo.
  }
}

void Transaction::Commit() {
  db_.Prepare(depth_ == 0 ? std::string("COMMIT") : "RELEASE rlpos_" + std::to_string(depth_))
      .Run();
  --db_.transaction_depth_;
  done_ = true;
}

}  // namespace rlpos
