#include "server/store/sqlite/SqliteStorage.h"

#include "server/store/sqlite/SqliteSchema.h"

namespace tlmhub::server {

SqliteStorage::SqliteStorage(const StorageConfig& config)
    : mDb(config)
{
    mDb.run([](SqliteConnection& c) { migrateSqlite(c); });
}

int SqliteStorage::schemaVersion()
{
    return mDb.run([](SqliteConnection& c) { return sqliteSchemaVersion(c); });
}

std::string SqliteStorage::describe() const { return "SQLite " + mDb.path(); }

} // namespace tlmhub::server
