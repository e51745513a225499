#include "server/store/sqlite/SqliteStores.h"

namespace tlmhub::server {

std::optional<std::string> SqliteMetaStore::get(const std::string& key)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT value FROM meta WHERE key = ?");
        q->bind(1, key);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

void SqliteMetaStore::set(const std::string& key, const std::string& value)
{
    mDb.run([&](SqliteConnection& c) {
        auto upsert = c.prepared("INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
        upsert->bind(1, key);
        upsert->bind(2, value);
        upsert->exec();
    });
}

bool SqliteMetaStore::insertIfAbsent(const std::string& key, const std::string& value)
{
    return mDb.run([&](SqliteConnection& c) {
        auto insert = c.prepared("INSERT OR IGNORE INTO meta(key, value) VALUES(?, ?)");
        insert->bind(1, key);
        insert->bind(2, value);
        return insert->exec() == 1;
    });
}

} // namespace tlmhub::server
