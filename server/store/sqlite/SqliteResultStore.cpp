#include "server/store/sqlite/SqliteStores.h"

namespace tlmhub::server {

std::optional<std::string> SqliteResultStore::blob(std::int64_t jobId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT data FROM job_results WHERE job_id = ?");
        q->bind(1, jobId);
        if (!q->executeStep()) return std::nullopt;
        const SQLite::Column data = q->getColumn(0);
        return std::string(static_cast<const char*>(data.getBlob()), static_cast<std::size_t>(data.getBytes()));
    });
}

bool SqliteResultStore::has(std::int64_t jobId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT 1 FROM job_results WHERE job_id = ?");
        q->bind(1, jobId);
        return q->executeStep();
    });
}

std::size_t SqliteResultStore::storedBytes(std::int64_t ownerId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT (SELECT COALESCE(SUM(length(r.data)), 0) FROM job_results r"
                            "        JOIN jobs j ON j.id = r.job_id WHERE j.owner_id = ?1)"
                            "     + (SELECT COALESCE(SUM(length(r.result)), 0) FROM study_runs r"
                            "        JOIN studies s ON s.id = r.study_id WHERE s.owner_id = ?1)");
        q->bind(1, ownerId);
        return q->executeStep() ? static_cast<std::size_t>(q->getColumn(0).getInt64()) : std::size_t(0);
    });
}

} // namespace tlmhub::server
