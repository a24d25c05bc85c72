#pragma once
// Thin RAII wrappers over the SQLite C API. Every SQLite error becomes a StoreError naming the
// database file and, where there is one, the statement that failed.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace rlpos {

class Database;
class Statement;

// A result column of a statement, found by its name (Statement::Column) and then read by the
// index that found: the only way to read a column, so that a reordered SELECT reads the same
// fields instead of swapping them.
class ResultColumn {
 private:
  friend class Statement;
  explicit ResultColumn(int index) : index_(index) {}
  int index_;
};

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql, const std::string& file);
  // Wraps a statement compiled earlier (from Database's cache).
  Statement(sqlite3* db, sqlite3_stmt* compiled, const std::string& sql, const std::string& file);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&&) = delete;

  // Binds the next parameter (1, 2, ... in call order).
  Statement& Bind(const std::string& value);
  Statement& Bind(const char* value) { return Bind(std::string(value)); }
  Statement& Bind(std::int64_t value);
  Statement& Bind(int value) { return Bind(static_cast<std::int64_t>(value)); }
  Statement& Bind(std::uint64_t value);
  Statement& Bind(double value);
  Statement& BindNull();
  template <typename T>
  Statement& Bind(const std::optional<T>& value) {
    return value ? Bind(*value) : BindNull();
  }

  // Runs one step: true when a row is available, false when done.
  bool Step();
  // Steps to completion (statements without rows).
  void Run();
  // Clears bindings and rewinds, for reuse with new parameters.
  void Reset();

  // The result column named `name`: its AS name, else the column's own (`j.id` is "id"). Look
  // it up once per statement, before reading its rows. Throws StoreError when the statement has
  // no column of that name, or two.
  ResultColumn Column(std::string_view name) const;

  bool IsNull(ResultColumn column) const;
  std::int64_t Int(ResultColumn column) const;
  double Double(ResultColumn column) const;
  std::string Text(ResultColumn column) const;
  std::optional<std::string> OptionalText(ResultColumn column) const;
  std::optional<std::int64_t> OptionalInt(ResultColumn column) const;
  std::optional<double> OptionalDouble(ResultColumn column) const;

 private:
  friend class Database;
  [[noreturn]] void Fail(int rc) const;
  Database* owner_ = nullptr;  // set: the compiled statement goes back to its cache
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;
  std::string file_;
  int next_ = 1;
};

class Database {
 public:
  // Opens (read-write: creating it if missing) with a busy timeout. Throws StoreError.
  Database(const std::string& file, bool read_only, int busy_timeout_ms);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  const std::string& file() const { return file_; }
  bool read_only() const { return read_only_; }
  // Runs constant SQL with no parameters (schema, pragmas). Throws StoreError.
  void Exec(const std::string& sql);
  // Compiled statements are cached by their SQL text: a statement the store runs for every job
  // is parsed once, not once per job.
  Statement Prepare(const std::string& sql);
  // Rows changed by the last INSERT/UPDATE/DELETE.
  int Changes() const;

 private:
  friend class Transaction;
  friend class Statement;
  void Release(const std::string& sql, sqlite3_stmt* stmt);  // back to the cache, reset
  std::unordered_map<std::string, std::vector<sqlite3_stmt*>> idle_;
  int transaction_depth_ = 0;  // open Transactions: the outermost BEGINs, the others SAVEPOINT
  sqlite3* db_ = nullptr;
  std::string file_;
  bool read_only_;
};

// BEGIN IMMEDIATE ... COMMIT, rolled back if not committed (an exception left the scope).
// IMMEDIATE takes the write lock up front, so a read-then-write never fails half-way on a lock.
// Transactions nest: an inner one is a SAVEPOINT, released or rolled back to on its own, and
// written to disk with the outermost (so a caller can batch many operations in one commit).
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void Commit();

 private:
  Database& db_;
  int depth_;  // 0: the outermost
  bool done_ = false;
};

}  // namespace rlpos
