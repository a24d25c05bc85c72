#pragma once
// The results store's schema, versioned: `schema_version` holds one row with the version, and
// migrations run in order, each in its own transaction, from the file's version to the newest.
// The schema is documented in docs/results-database.md; change both together, and only by appending
// a migration (never by editing one that has shipped).
#include <functional>
#include <vector>

#include "common/store/sqlite_db.h"

namespace rlpos {

struct Migration {
  int version;      // the schema version after this migration
  const char* sql;  // constant DDL, no parameters
  // Runs after `sql`, in the same transaction: data conversions SQL cannot express.
  std::function<void(Database&)> convert;
  // Runs after `convert`: DDL that needs the converted data (e.g. dropping the old column).
  const char* sql_after = nullptr;
};

// In order; versions are 1, 2, 3, ...
const std::vector<Migration>& Migrations();
int LatestSchemaVersion();

// The file's version: 0 for a new (empty) database. Throws StoreError for an SQLite file that is
// not a results store.
int ReadSchemaVersion(Database& db);

// Brings the file to the latest version. Throws StoreError naming the file when its version is
// newer than this build knows, or older and the database is opened read-only.
void MigrateSchema(Database& db);

}  // namespace rlpos
