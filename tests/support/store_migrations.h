#pragma once
// A results store at an old schema version, for the tests of what a migration keeps.
#include "common/store/sqlite_db.h"

namespace rlpos::testing {

// Runs the store's migrations 1 to `version` on `db`, as the store would have, without
// recording the version (schema_version is the caller's to write, or not).
void MigrateUpTo(Database& db, int version);

}  // namespace rlpos::testing
