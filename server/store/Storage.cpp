#include "server/store/Storage.h"

#include "server/store/postgres/PostgresStorage.h"
#include "server/store/sqlite/SqliteStorage.h"

namespace tlmhub::server {

bool isPostgresUri(const std::string& database)
{
    return database.starts_with("postgresql://") || database.starts_with("postgres://");
}

StoreError schemaNewerThanThisServer(int version)
{
    return StoreError(StoreErrc::Corrupt, "the database is at schema version " + std::to_string(version) +
                                              ", newer than this server's " + std::to_string(kSchemaVersion) +
                                              "; run a newer tlmhub-server");
}

std::unique_ptr<Storage> openStorage(const StorageConfig& config)
{
    if (isPostgresUri(config.database)) return openPostgresStorage(config);
    return std::make_unique<SqliteStorage>(config);
}

} // namespace tlmhub::server
