#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kForget{"idempotency_forget",
                              "DELETE FROM idempotency_keys WHERE owner_id = $1 AND created_at < $2"};
// Inserts the pending reservation, or leaves the row there as it is: RETURNING then gives
// nothing, and the row is read after.
constexpr PgStatement kReserve{"idempotency_reserve",
                               "INSERT INTO idempotency_keys(owner_id, key, route, request_hash, object_id, created_at)"
                               " VALUES($1, $2, $3, $4, 0, $5) ON CONFLICT (owner_id, key) DO NOTHING RETURNING owner_id"};
constexpr PgStatement kFind{"idempotency_find", "SELECT route, request_hash, object_id FROM idempotency_keys"
                                                " WHERE owner_id = $1 AND key = $2"};
constexpr PgStatement kComplete{"idempotency_complete",
                                "UPDATE idempotency_keys SET object_id = $3 WHERE owner_id = $1 AND key = $2"};
constexpr PgStatement kRelease{"idempotency_release",
                               "DELETE FROM idempotency_keys WHERE owner_id = $1 AND key = $2 AND object_id = 0"};

} // namespace

std::optional<IdempotencyKey> PostgresIdempotencyKeyStore::reserve(std::int64_t ownerId, const std::string& key,
                                                                   const IdempotencyKey& use, std::int64_t nowUnix,
                                                                   std::int64_t notBeforeUnix)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<IdempotencyKey> {
        pqxx::work tx(c.raw());
        c.exec(tx, kForget, ownerId, notBeforeUnix);
        // The insert waits for a racing attempt's uncommitted row with the same key and then
        // does nothing, so exactly one of them reserves it.
        if (!c.exec(tx, kReserve, ownerId, key, use.route, use.requestHash, nowUnix).empty()) {
            tx.commit();
            return std::nullopt;
        }
        const auto r = c.exec(tx, kFind, ownerId, key);
        tx.commit();
        if (r.empty()) return IdempotencyKey{use.route, use.requestHash, 0};   // released meanwhile: still pending to this caller
        return IdempotencyKey{r[0][0].as<std::string>(), r[0][1].as<std::string>(), r[0][2].as<std::int64_t>()};
    });
}

void PostgresIdempotencyKeyStore::complete(std::int64_t ownerId, const std::string& key, std::int64_t objectId)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kComplete, ownerId, key, objectId);
    });
}

void PostgresIdempotencyKeyStore::release(std::int64_t ownerId, const std::string& key)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kRelease, ownerId, key);
    });
}

} // namespace tlmhub::server
