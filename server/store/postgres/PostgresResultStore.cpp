#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kBlob{"results_blob", "SELECT data FROM job_results WHERE job_id = $1"};
constexpr PgStatement kHas{"results_has", "SELECT 1 FROM job_results WHERE job_id = $1"};
constexpr PgStatement kStoredBytes{"results_stored_bytes",
                                   "SELECT ((SELECT COALESCE(SUM(octet_length(r.data)), 0) FROM job_results r"
                                   "         JOIN jobs j ON j.id = r.job_id WHERE j.owner_id = $1)"
                                   "      + (SELECT COALESCE(SUM(octet_length(r.result)), 0) FROM study_runs r"
                                   "         JOIN studies s ON s.id = r.study_id WHERE s.owner_id = $1))::BIGINT"};

} // namespace

std::optional<std::string> PostgresResultStore::blob(std::int64_t jobId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kBlob, jobId);
        if (r.empty()) return std::nullopt;
        // The text form of bytea, decoded back to the stored bytes.
        const pqxx::binarystring data(r[0][0]);
        return data.str();
    });
}

bool PostgresResultStore::has(std::int64_t jobId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return !c.exec(tx, kHas, jobId).empty();
    });
}

std::size_t PostgresResultStore::storedBytes(std::int64_t ownerId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kStoredBytes, ownerId)[0][0].as<std::size_t>();
    });
}

} // namespace tlmhub::server
