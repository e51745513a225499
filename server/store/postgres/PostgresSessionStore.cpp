#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kPurge{"sessions_purge", "DELETE FROM sessions WHERE expires_at <= $1"};
constexpr PgStatement kInsert{"sessions_insert",
                              "INSERT INTO sessions(token_hash, user_id, expires_at) VALUES($1, $2, $3)"};
constexpr PgStatement kUserOf{"sessions_user_of", "SELECT user_id, expires_at FROM sessions WHERE token_hash = $1"};
constexpr PgStatement kRemove{"sessions_remove", "DELETE FROM sessions WHERE token_hash = $1"};
constexpr PgStatement kRemoveAllFor{"sessions_remove_all_for", "DELETE FROM sessions WHERE user_id = $1"};

} // namespace

void PostgresSessionStore::insert(const std::string& tokenHash, std::int64_t userId, std::int64_t expiresAt,
                                  std::int64_t now)
{
    mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        c.exec(tx, kPurge, now);
        c.exec(tx, kInsert, tokenHash, userId, expiresAt);
        tx.commit();
    });
}

std::optional<std::int64_t> PostgresSessionStore::userOf(const std::string& tokenHash, std::int64_t now)
{
    // Reading again after a broken connection is harmless, and so is deleting an expired
    // session twice.
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kUserOf, tokenHash);
        if (r.empty()) return std::nullopt;
        if (r[0][1].as<std::int64_t>(0) > now) return r[0][0].as<std::int64_t>();
        c.exec(tx, kRemove, tokenHash);
        return std::nullopt;
    });
}

void PostgresSessionStore::remove(const std::string& tokenHash)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kRemove, tokenHash);
    });
}

void PostgresSessionStore::removeAllFor(std::int64_t userId)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kRemoveAllFor, userId);
    });
}

} // namespace tlmhub::server
