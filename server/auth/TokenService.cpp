#include "server/auth/TokenService.h"

#include "server/auth/Sodium.h"

#include <SQLiteCpp/Statement.h>
#include <sodium.h>

namespace tlmhub::server {

namespace {

constexpr std::size_t kTokenBytes = 32;

std::string tokenHash(const std::string& token)
{
    ensureSodium();
    unsigned char digest[crypto_generichash_BYTES];
    crypto_generichash(digest, sizeof digest, reinterpret_cast<const unsigned char*>(token.data()),
                       token.size(), nullptr, 0);
    char hex[crypto_generichash_BYTES * 2 + 1];
    sodium_bin2hex(hex, sizeof hex, digest, sizeof digest);
    return hex;
}

} // namespace

TokenService::TokenService(Database& db, std::chrono::seconds ttl, UserStore& users)
    : mDb(db), mTtl(ttl), mUsers(users)
{
    std::lock_guard lock(mDb.mutex());
    mDb.sql().exec(
        "CREATE TABLE IF NOT EXISTS sessions ("
        " token_hash TEXT PRIMARY KEY,"
        " user_id INTEGER REFERENCES users(id) ON DELETE CASCADE,"
        " expires_at INTEGER)");
}

TokenService::Issued TokenService::issue(const User& user)
{
    Issued issued{randomHex(kTokenBytes), static_cast<std::int64_t>(unixNow()) + mTtl.count()};
    const std::string hash = tokenHash(issued.token);
    std::lock_guard lock(mDb.mutex());
    // On a full disk too: logging in is how an owner gets to delete what fills it.
    mDb.freeingSpace([&] {
        // Expired sessions of nobody in particular are cleared here so the table stays small
        // even when clients never log out.
        SQLite::Statement purge(mDb.sql(), "DELETE FROM sessions WHERE expires_at <= ?");
        purge.bind(1, static_cast<std::int64_t>(unixNow()));
        purge.exec();
        SQLite::Statement insert(mDb.sql(),
                                 "INSERT INTO sessions(token_hash, user_id, expires_at) VALUES(?, ?, ?)");
        insert.bind(1, hash);
        insert.bind(2, user.id);
        insert.bind(3, issued.expiresAt);
        insert.exec();
    });
    return issued;
}

std::optional<User> TokenService::validate(const std::string& token)
{
    if (token.size() != kTokenBytes * 2) return std::nullopt;
    const std::string hash = tokenHash(token);
    std::int64_t userId = 0;
    {
        std::lock_guard lock(mDb.mutex());
        SQLite::Statement q(mDb.sql(),
                            "SELECT user_id, expires_at FROM sessions WHERE token_hash = ?");
        q.bind(1, hash);
        if (!q.executeStep()) return std::nullopt;
        userId = q.getColumn(0).getInt64();
        if (q.getColumn(1).getInt64() <= static_cast<std::int64_t>(unixNow())) {
            q.reset();
            SQLite::Statement remove(mDb.sql(), "DELETE FROM sessions WHERE token_hash = ?");
            remove.bind(1, hash);
            remove.exec();
            return std::nullopt;
        }
    }
    // Outside the lock: UserStore takes the same mutex.
    auto user = mUsers.find(userId);
    if (user && user->disabled) return std::nullopt;
    return user;
}

void TokenService::revoke(const std::string& token)
{
    const std::string hash = tokenHash(token);
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement remove(mDb.sql(), "DELETE FROM sessions WHERE token_hash = ?");
    remove.bind(1, hash);
    remove.exec();
}

void TokenService::revokeAllFor(std::int64_t userId)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement remove(mDb.sql(), "DELETE FROM sessions WHERE user_id = ?");
    remove.bind(1, userId);
    remove.exec();
}

} // namespace tlmhub::server
