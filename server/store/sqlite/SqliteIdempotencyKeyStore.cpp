#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>

namespace tlmhub::server {

std::optional<IdempotencyKey> SqliteIdempotencyKeyStore::reserve(std::int64_t ownerId, const std::string& key,
                                                                 const IdempotencyKey& use, std::int64_t nowUnix,
                                                                 std::int64_t notBeforeUnix)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<IdempotencyKey> {
        // IMMEDIATE: the write lock before the read, so no other attempt reserves in between.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto forget = c.prepared("DELETE FROM idempotency_keys WHERE owner_id = ? AND created_at < ?");
            forget->bind(1, ownerId);
            forget->bind(2, notBeforeUnix);
            forget->exec();
        }
        {
            auto find = c.prepared("SELECT route, request_hash, object_id FROM idempotency_keys"
                                   " WHERE owner_id = ? AND key = ?");
            find->bind(1, ownerId);
            find->bind(2, key);
            if (find->executeStep())
                return IdempotencyKey{find->getColumn(0).getString(), find->getColumn(1).getString(),
                                      find->getColumn(2).getInt64()};
        }
        auto insert = c.prepared("INSERT INTO idempotency_keys(owner_id, key, route, request_hash, object_id, created_at)"
                                 " VALUES(?, ?, ?, ?, 0, ?)");
        insert->bind(1, ownerId);
        insert->bind(2, key);
        insert->bind(3, use.route);
        insert->bind(4, use.requestHash);
        insert->bind(5, nowUnix);
        insert->exec();
        transaction.commit();
        return std::nullopt;
    });
}

void SqliteIdempotencyKeyStore::complete(std::int64_t ownerId, const std::string& key, std::int64_t objectId)
{
    mDb.run([&](SqliteConnection& c) {
        auto update = c.prepared("UPDATE idempotency_keys SET object_id = ? WHERE owner_id = ? AND key = ?");
        update->bind(1, objectId);
        update->bind(2, ownerId);
        update->bind(3, key);
        update->exec();
    });
}

void SqliteIdempotencyKeyStore::release(std::int64_t ownerId, const std::string& key)
{
    // Frees space: a request refused for a full disk must not leave its key stuck.
    mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto remove = c.prepared("DELETE FROM idempotency_keys WHERE owner_id = ? AND key = ? AND object_id = 0");
        remove->bind(1, ownerId);
        remove->bind(2, key);
        remove->exec();
    });
}

} // namespace tlmhub::server
