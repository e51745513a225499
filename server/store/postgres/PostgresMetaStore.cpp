#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kGet{"meta_get", "SELECT value FROM meta WHERE key = $1"};
constexpr PgStatement kSet{"meta_set", "INSERT INTO meta(key, value) VALUES($1, $2)"
                                       " ON CONFLICT (key) DO UPDATE SET value = EXCLUDED.value"};
constexpr PgStatement kInsertIfAbsent{"meta_insert_if_absent", "INSERT INTO meta(key, value) VALUES($1, $2)"
                                                               " ON CONFLICT (key) DO NOTHING"};

} // namespace

std::optional<std::string> PostgresMetaStore::get(const std::string& key)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kGet, key);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>(std::string());
    });
}

void PostgresMetaStore::set(const std::string& key, const std::string& value)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kSet, key, value);
    });
}

bool PostgresMetaStore::insertIfAbsent(const std::string& key, const std::string& value)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kInsertIfAbsent, key, value).affected_rows() == 1;
    });
}

} // namespace tlmhub::server
