#pragma once
// The PostgreSQL schema as numbered migrations, the same versions as SQLite's
// (server/store/sqlite/SqliteSchema.cpp), recorded in table schema_migrations.
#include "server/store/postgres/PostgresConnection.h"

namespace tlmhub::server {

// Applies, each in its own transaction, every migration newer than the database's version.
// Servers starting at once on one database take turns (an advisory lock held by each
// migration's transaction), so every migration is applied once. Throws StoreError(Corrupt)
// for a database that a newer build has migrated past this one's.
void migratePostgres(PostgresConnection& connection);
int postgresSchemaVersion(PostgresConnection& connection);

} // namespace tlmhub::server
