#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kAdd{"sign_in_add",
                           "INSERT INTO sign_in_attempts(state, provider, nonce, code_verifier, browser_key, created_at, user_id)"
                           " VALUES($1, $2, $3, $4, $5, $6, $7)"};
constexpr PgStatement kTake{"sign_in_take", "DELETE FROM sign_in_attempts WHERE state = $1"
                                            " RETURNING provider, nonce, code_verifier, browser_key, created_at, user_id"};
constexpr PgStatement kPurge{"sign_in_purge", "DELETE FROM sign_in_attempts WHERE created_at < $1"};
constexpr PgStatement kCount{"sign_in_count", "SELECT COUNT(*) FROM sign_in_attempts"};

} // namespace

void PostgresSignInStore::add(const SignInAttempt& attempt)
{
    mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kAdd, attempt.state, attempt.provider, attempt.nonce, attempt.codeVerifier, attempt.browserKey,
               attempt.createdAt, attempt.userId);
    });
}

std::optional<SignInAttempt> PostgresSignInStore::take(const std::string& state, std::int64_t notBeforeUnix)
{
    // Not retried: a delete that committed before the connection broke has taken the attempt.
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<SignInAttempt> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kTake, state);
        if (r.empty()) return std::nullopt;
        SignInAttempt attempt{state, r[0][0].as<std::string>(), r[0][1].as<std::string>(), r[0][2].as<std::string>(),
                              r[0][3].as<std::string>(), r[0][4].as<std::int64_t>(), r[0][5].as<std::int64_t>()};
        if (attempt.createdAt < notBeforeUnix) return std::nullopt;
        return attempt;
    });
}

std::size_t PostgresSignInStore::purge(std::int64_t notBeforeUnix)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kPurge, notBeforeUnix);
        return static_cast<std::size_t>(c.exec(tx, kCount)[0][0].as<std::int64_t>());
    });
}

} // namespace tlmhub::server
