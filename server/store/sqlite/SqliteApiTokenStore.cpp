#include "server/store/sqlite/SqliteStores.h"

#include <sqlite3.h>

namespace tlmhub::server {

namespace {

// A use is recorded when the last one is at least this old, so a busy script does not write
// on every call.
constexpr std::int64_t kLastUseResolution = 60;   // s

ApiTokenInfo readToken(SQLite::Statement& q)
{
    ApiTokenInfo t;
    t.id = q.getColumn(0).getInt64();
    t.userId = q.getColumn(1).getInt64();
    t.name = q.getColumn(2).getString();
    t.createdAt = q.getColumn(3).getInt64();
    if (!q.getColumn(4).isNull()) t.expiresAt = q.getColumn(4).getInt64();
    if (!q.getColumn(5).isNull()) t.lastUsedAt = q.getColumn(5).getInt64();
    return t;
}

} // namespace

std::optional<std::int64_t> SqliteApiTokenStore::insert(std::int64_t userId, const std::string& name,
                                                        const std::string& tokenHash, std::int64_t createdAt,
                                                        std::optional<std::int64_t> expiresAt)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        auto insert = c.prepared("INSERT INTO api_tokens(user_id, name, token_hash, created_at, expires_at)"
                                 " VALUES(?, ?, ?, ?, ?)");
        insert->bind(1, userId);
        insert->bind(2, name);
        insert->bind(3, tokenHash);
        insert->bind(4, createdAt);
        if (expiresAt) insert->bind(5, *expiresAt);
        else insert->bind(5);
        try {
            insert->exec();
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;
            throw;
        }
        return c.db().getLastInsertRowid();
    });
}

std::optional<ApiTokenInfo> SqliteApiTokenStore::use(const std::string& tokenHash, std::int64_t now)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<ApiTokenInfo> {
        ApiTokenInfo token;
        {
            auto q = c.prepared("SELECT id, user_id, name, created_at, expires_at, last_used_at"
                                " FROM api_tokens WHERE token_hash = ?");
            q->bind(1, tokenHash);
            if (!q->executeStep()) return std::nullopt;
            token = readToken(*q);
        }
        if (token.expiresAt && *token.expiresAt <= now) return std::nullopt;
        if (token.lastUsedAt && now - *token.lastUsedAt < kLastUseResolution) return token;
        auto record = c.prepared("UPDATE api_tokens SET last_used_at = ? WHERE id = ?");
        record->bind(1, now);
        record->bind(2, token.id);
        try {
            record->exec();
            token.lastUsedAt = now;
        } catch (const SQLite::Exception& e) {
            // The last use is a hint: a full disk must not lock scripts out.
            if (!isDiskFull(e)) throw;
        }
        return token;
    });
}

std::vector<ApiTokenInfo> SqliteApiTokenStore::list(std::int64_t userId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT id, user_id, name, created_at, expires_at, last_used_at"
                            " FROM api_tokens WHERE user_id = ? ORDER BY id DESC");
        q->bind(1, userId);
        std::vector<ApiTokenInfo> tokens;
        while (q->executeStep()) tokens.push_back(readToken(*q));
        return tokens;
    });
}

std::size_t SqliteApiTokenStore::count(std::int64_t userId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT COUNT(*) FROM api_tokens WHERE user_id = ?");
        q->bind(1, userId);
        q->executeStep();
        return static_cast<std::size_t>(q->getColumn(0).getInt64());
    });
}

bool SqliteApiTokenStore::remove(std::int64_t userId, std::int64_t id)
{
    // Revoking is how a leaked token is stopped: on a full disk too.
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM api_tokens WHERE id = ? AND user_id = ?");
        q->bind(1, id);
        q->bind(2, userId);
        return q->exec() == 1;
    });
    mDb.restoreReserve();
    return removed;
}

std::size_t SqliteApiTokenStore::removeAll(std::int64_t userId)
{
    // As remove(): disabling an account must stop its scripts on a full disk too.
    const std::size_t removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM api_tokens WHERE user_id = ?");
        q->bind(1, userId);
        return static_cast<std::size_t>(q->exec());
    });
    mDb.restoreReserve();
    return removed;
}

} // namespace tlmhub::server
