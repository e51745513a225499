#include "server/store/UnixTime.h"
#include "server/store/sqlite/SqliteStores.h"

#include <sqlite3.h>

namespace tlmhub::server {

namespace {

// The summary columns (readSummary's order), for one model and for all.
constexpr const char* kSummaryById =
    "SELECT m.id, m.name, m.owner_id, u.username, u.role, m.is_example, m.created_at,"
    " m.updated_at FROM models m LEFT JOIN users u ON u.id = m.owner_id WHERE m.id = ?";
constexpr const char* kSummariesById =
    "SELECT m.id, m.name, m.owner_id, u.username, u.role, m.is_example, m.created_at,"
    " m.updated_at FROM models m LEFT JOIN users u ON u.id = m.owner_id ORDER BY m.id";

ModelSummary readSummary(SQLite::Statement& q)
{
    ModelSummary s;
    s.id = q.getColumn(0).getInt64();
    s.name = q.getColumn(1).getString();
    s.ownerId = q.getColumn(2).getInt64();
    s.ownerName = q.getColumn(3).getString();
    s.ownerRole = q.getColumn(4).getString();
    s.isExample = q.getColumn(5).getInt64() != 0;
    s.createdAt = q.getColumn(6).getInt64();
    s.updatedAt = q.getColumn(7).getInt64();
    return s;
}

} // namespace

std::optional<std::int64_t> SqliteModelStore::create(std::int64_t ownerId, const std::string& name,
                                                     const std::string& hmf, bool isExample)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        auto insert = c.prepared("INSERT INTO models(owner_id, name, hmf, is_example, created_at,"
                                 " updated_at) VALUES(?, ?, ?, ?, ?, ?)");
        insert->bind(1, ownerId);
        insert->bind(2, name);
        insert->bind(3, hmf);
        insert->bind(4, isExample ? 1 : 0);
        insert->bind(5, now);
        insert->bind(6, now);
        try {
            insert->exec();
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;
            throw;
        }
        return c.db().getLastInsertRowid();
    });
}

std::optional<ModelSummary> SqliteModelStore::summary(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<ModelSummary> {
        auto q = c.prepared(kSummaryById);
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readSummary(*q);
    });
}

std::optional<std::string> SqliteModelStore::hmf(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT hmf FROM models WHERE id = ?");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

bool SqliteModelStore::update(std::int64_t id, const std::optional<std::string>& name,
                              const std::optional<std::string>& hmf)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        // COALESCE keeps a field whose new value is NULL (not given).
        auto update = c.prepared("UPDATE models SET name = COALESCE(?, name), hmf = COALESCE(?, hmf),"
                                 " updated_at = ? WHERE id = ?");
        if (name) update->bind(1, *name); else update->bind(1);
        if (hmf) update->bind(2, *hmf); else update->bind(2);
        update->bind(3, now);
        update->bind(4, id);
        return update->exec() > 0;
    });
}

bool SqliteModelStore::remove(std::int64_t id)
{
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto remove = c.prepared("DELETE FROM models WHERE id = ?");
        remove->bind(1, id);
        return remove->exec() > 0;
    });
    mDb.restoreReserve();
    return removed;
}

std::vector<ModelSummary> SqliteModelStore::list()
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kSummariesById);
        std::vector<ModelSummary> all;
        while (q->executeStep()) all.push_back(readSummary(*q));
        return all;
    });
}

} // namespace tlmhub::server
