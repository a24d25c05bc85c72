#include "tests/support/store_migrations.h"

#include "common/store/schema.h"

namespace rlpos::testing {

void MigrateUpTo(Database& db, int version) {
  for (const Migration& m : Migrations()) {
    if (m.version > version)
      break;
    db.Exec(m.sql);
    if (m.convert)
      m.convert(db);
    if (m.sql_after)
      db.Exec(m.sql_after);
  }
}

}  // namespace rlpos::testing
