#pragma once
// The SQLite schema as numbered migrations, recorded in table schema_migrations.
#include "server/store/sqlite/SqliteConnection.h"

namespace tlmhub::server {

// Applies, each in its own transaction, every migration newer than the database's version.
// A data directory from before migrations existed (its tables made at start by each store)
// is at version 0 and upgrades in place. Throws StoreError(Corrupt) for a database that a
// newer build has migrated past this one's.
void migrateSqlite(SqliteConnection& connection);
int sqliteSchemaVersion(SqliteConnection& connection);

} // namespace tlmhub::server
