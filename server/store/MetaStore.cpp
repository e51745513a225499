#include "server/store/MetaStore.h"

#include <SQLiteCpp/Statement.h>

namespace tlmhub::server {

MetaStore::MetaStore(Database& db) : mDb(db)
{
    std::lock_guard lock(mDb.mutex());
    mDb.sql().exec("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT)");
}

std::optional<std::string> MetaStore::get(const std::string& key)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT value FROM meta WHERE key = ?");
    q.bind(1, key);
    if (!q.executeStep()) return std::nullopt;
    return q.getColumn(0).getString();
}

void MetaStore::set(const std::string& key, const std::string& value)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement upsert(mDb.sql(), "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
    upsert.bind(1, key);
    upsert.bind(2, value);
    upsert.exec();
}

} // namespace tlmhub::server
