#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

// A use is recorded when the last one is at least this old, so a busy script does not write
// on every call.
constexpr std::int64_t kLastUseResolution = 60;   // s

constexpr PgStatement kInsert{"api_tokens_insert",
                              "INSERT INTO api_tokens(user_id, name, token_hash, created_at, expires_at)"
                              " VALUES($1, $2, $3, $4, $5) RETURNING id"};
constexpr PgStatement kFind{"api_tokens_find",
                            "SELECT id, user_id, name, created_at, expires_at, last_used_at FROM api_tokens"
                            " WHERE token_hash = $1"};
constexpr PgStatement kRecordUse{"api_tokens_record_use", "UPDATE api_tokens SET last_used_at = $1 WHERE id = $2"};
constexpr PgStatement kList{"api_tokens_list",
                            "SELECT id, user_id, name, created_at, expires_at, last_used_at FROM api_tokens"
                            " WHERE user_id = $1 ORDER BY id DESC"};
constexpr PgStatement kCount{"api_tokens_count", "SELECT COUNT(*) FROM api_tokens WHERE user_id = $1"};
constexpr PgStatement kRemove{"api_tokens_remove", "DELETE FROM api_tokens WHERE id = $1 AND user_id = $2"};
constexpr PgStatement kRemoveAll{"api_tokens_remove_all", "DELETE FROM api_tokens WHERE user_id = $1"};

ApiTokenInfo readToken(const pqxx::row& row)
{
    ApiTokenInfo t;
    t.id = row[0].as<std::int64_t>();
    t.userId = row[1].as<std::int64_t>();
    t.name = row[2].as<std::string>();
    t.createdAt = row[3].as<std::int64_t>();
    t.expiresAt = nullable<std::int64_t>(row[4]);
    t.lastUsedAt = nullable<std::int64_t>(row[5]);
    return t;
}

} // namespace

std::optional<std::int64_t> PostgresApiTokenStore::insert(std::int64_t userId, const std::string& name,
                                                          const std::string& tokenHash, std::int64_t createdAt,
                                                          std::optional<std::int64_t> expiresAt)
{
    const std::optional<std::string> expires = expiresAt ? std::optional(std::to_string(*expiresAt)) : std::nullopt;
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kInsert, userId, name, tokenHash, createdAt, orNull(expires))[0][0].as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such user
        }
    });
}

std::optional<ApiTokenInfo> PostgresApiTokenStore::use(const std::string& tokenHash, std::int64_t now)
{
    // Reading again after a broken connection is harmless, and so is recording a use twice.
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<ApiTokenInfo> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kFind, tokenHash);
        if (r.empty()) return std::nullopt;
        ApiTokenInfo token = readToken(r[0]);
        if (token.expiresAt && *token.expiresAt <= now) return std::nullopt;
        if (token.lastUsedAt && now - *token.lastUsedAt < kLastUseResolution) return token;
        c.exec(tx, kRecordUse, now, token.id);
        token.lastUsedAt = now;
        return token;
    });
}

std::vector<ApiTokenInfo> PostgresApiTokenStore::list(std::int64_t userId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<ApiTokenInfo> tokens;
        for (const auto& row : c.exec(tx, kList, userId)) tokens.push_back(readToken(row));
        return tokens;
    });
}

std::size_t PostgresApiTokenStore::count(std::int64_t userId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kCount, userId)[0][0].as<std::size_t>();
    });
}

bool PostgresApiTokenStore::remove(std::int64_t userId, std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemove, id, userId).affected_rows() > 0;
    });
}

std::size_t PostgresApiTokenStore::removeAll(std::int64_t userId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return static_cast<std::size_t>(c.exec(tx, kRemoveAll, userId).affected_rows());
    });
}

} // namespace tlmhub::server
