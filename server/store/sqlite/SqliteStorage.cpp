#include "server/store/sqlite/SqliteStorage.h"

#include "server/store/sqlite/SqliteSchema.h"

namespace tlmhub::server {

SqliteStorage::SqliteStorage(const StorageConfig& config)
    : mDb(config.database, config.maxConnections, config.reserveBytes)
{
    mDb.run([](SqliteConnection& c) { migrateSqlite(c); });
}

int SqliteStorage::schemaVersion()
{
    return mDb.run([](SqliteConnection& c) { return sqliteSchemaVersion(c); });
}

std::string SqliteStorage::describe() const { return "SQLite " + mDb.path(); }

void SqliteStorage::backup(const std::filesystem::path& file)
{
    // VACUUM INTO reads in one transaction, so the copy is one consistent state of the file.
    mDb.run([&](SqliteConnection& c) {
        SQLite::Statement vacuum(c.db(), "VACUUM INTO ?");
        vacuum.bind(1, file.string());
        vacuum.exec();
    });
}

} // namespace tlmhub::server
