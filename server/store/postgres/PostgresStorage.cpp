#include "server/store/postgres/PostgresStorage.h"

#include "server/store/postgres/PostgresSchema.h"

namespace tlmhub::server {

PostgresStorage::PostgresStorage(const StorageConfig& config)
    : mDb(config.database, config.maxConnections)
{
    // Safe to run again on a fresh connection: each step reads the version under the lock.
    mDb.run(Idempotent::Yes, [](PostgresConnection& c) { migratePostgres(c); });
}

int PostgresStorage::schemaVersion()
{
    return mDb.run(Idempotent::Yes, [](PostgresConnection& c) { return postgresSchemaVersion(c); });
}

std::string PostgresStorage::describe() const
{
    return "PostgreSQL " + mDb.endpoint();
}

void PostgresStorage::backup(const std::filesystem::path&)
{
    throw StoreError(StoreErrc::Unavailable, "the server does not back up a PostgreSQL database itself;"
                                             " use pg_dump (see docs/storage.md)");
}

std::unique_ptr<Storage> openPostgresStorage(const StorageConfig& config)
{
    return std::make_unique<PostgresStorage>(config);
}

} // namespace tlmhub::server
