#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kCreate{"models_create",
                              "INSERT INTO models(owner_id, name, hmf, is_example, created_at, updated_at)"
                              " VALUES($1, $2, $3, $4, $5, $5) RETURNING id"};
constexpr PgStatement kSummary{"models_summary",
                               "SELECT m.id, m.name, m.owner_id, u.username, u.role, m.is_example,"
                               " m.created_at, m.updated_at FROM models m LEFT JOIN users u ON u.id = m.owner_id"
                               " WHERE m.id = $1"};
constexpr PgStatement kList{"models_list",
                            "SELECT m.id, m.name, m.owner_id, u.username, u.role, m.is_example,"
                            " m.created_at, m.updated_at FROM models m LEFT JOIN users u ON u.id = m.owner_id"
                            " ORDER BY m.id"};
constexpr PgStatement kHmf{"models_hmf", "SELECT hmf FROM models WHERE id = $1"};
// COALESCE keeps a field whose new value is NULL (not given).
constexpr PgStatement kUpdate{"models_update",
                              "UPDATE models SET name = COALESCE($1, name), hmf = COALESCE($2, hmf),"
                              " updated_at = $3 WHERE id = $4"};
constexpr PgStatement kRemove{"models_remove", "DELETE FROM models WHERE id = $1"};

ModelSummary readSummary(const pqxx::row& row)
{
    ModelSummary s;
    s.id = row[0].as<std::int64_t>();
    s.name = row[1].as<std::string>(std::string());
    s.ownerId = row[2].as<std::int64_t>(0);
    s.ownerName = row[3].as<std::string>(std::string());
    s.ownerRole = row[4].as<std::string>(std::string());
    s.isExample = row[5].as<bool>(false);
    s.createdAt = row[6].as<std::int64_t>(0);
    s.updatedAt = row[7].as<std::int64_t>(0);
    return s;
}

} // namespace

std::optional<std::int64_t> PostgresModelStore::create(std::int64_t ownerId, const std::string& name,
                                                       const std::string& hmf, bool isExample)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kCreate, ownerId, name, hmf, isExample, static_cast<std::int64_t>(unixNow()))[0][0]
                .as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such owner
        }
    });
}

std::optional<ModelSummary> PostgresModelStore::summary(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<ModelSummary> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kSummary, id);
        if (r.empty()) return std::nullopt;
        return readSummary(r[0]);
    });
}

std::optional<std::string> PostgresModelStore::hmf(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kHmf, id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>(std::string());
    });
}

bool PostgresModelStore::update(std::int64_t id, const std::optional<std::string>& name,
                                const std::optional<std::string>& hmf)
{
    // Running it twice sets the same fields; only updated_at moves on by the retry's delay.
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kUpdate, orNull(name), orNull(hmf), static_cast<std::int64_t>(unixNow()), id)
                   .affected_rows() > 0;
    });
}

bool PostgresModelStore::remove(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemove, id).affected_rows() > 0;
    });
}

std::vector<ModelSummary> PostgresModelStore::list()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<ModelSummary> models;
        for (const auto& row : c.exec(tx, kList)) models.push_back(readSummary(row));
        return models;
    });
}

} // namespace tlmhub::server
