#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>

namespace tlmhub::server {

void SqliteSessionStore::insert(const std::string& tokenHash, std::int64_t userId, std::int64_t expiresAt,
                                std::int64_t now)
{
    mDb.runFreeingSpace([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto purge = c.prepared("DELETE FROM sessions WHERE expires_at <= ?");
            purge->bind(1, now);
            purge->exec();
        }
        auto insert = c.prepared("INSERT INTO sessions(token_hash, user_id, expires_at) VALUES(?, ?, ?)");
        insert->bind(1, tokenHash);
        insert->bind(2, userId);
        insert->bind(3, expiresAt);
        insert->exec();
        transaction.commit();
    });
}

std::optional<std::int64_t> SqliteSessionStore::userOf(const std::string& tokenHash, std::int64_t now)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        std::int64_t userId = 0;
        {
            auto q = c.prepared("SELECT user_id, expires_at FROM sessions WHERE token_hash = ?");
            q->bind(1, tokenHash);
            if (!q->executeStep()) return std::nullopt;
            userId = q->getColumn(0).getInt64();
            if (q->getColumn(1).getInt64() > now) return userId;
        }
        auto remove = c.prepared("DELETE FROM sessions WHERE token_hash = ?");
        remove->bind(1, tokenHash);
        remove->exec();
        return std::nullopt;
    });
}

void SqliteSessionStore::remove(const std::string& tokenHash)
{
    mDb.run([&](SqliteConnection& c) {
        auto remove = c.prepared("DELETE FROM sessions WHERE token_hash = ?");
        remove->bind(1, tokenHash);
        remove->exec();
    });
}

void SqliteSessionStore::removeAllFor(std::int64_t userId)
{
    mDb.run([&](SqliteConnection& c) {
        auto remove = c.prepared("DELETE FROM sessions WHERE user_id = ?");
        remove->bind(1, userId);
        remove->exec();
    });
}

} // namespace tlmhub::server
