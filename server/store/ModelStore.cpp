#include "server/store/ModelStore.h"

#include "server/auth/AccessPolicy.h"

#include <SQLiteCpp/Statement.h>

namespace tlmhub::server {

namespace {

constexpr const char* kSummaryColumns =
    "SELECT m.id, m.name, m.owner_id, u.username, u.role, m.is_example, m.created_at,"
    " m.updated_at FROM models m LEFT JOIN users u ON u.id = m.owner_id";

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

ModelStore::ModelStore(Database& db) : mDb(db)
{
    std::lock_guard lock(mDb.mutex());
    mDb.sql().exec(
        "CREATE TABLE IF NOT EXISTS models ("
        " id INTEGER PRIMARY KEY,"
        " owner_id INTEGER REFERENCES users(id),"
        " name TEXT,"
        " hmf TEXT,"
        " is_example INTEGER,"
        " created_at INTEGER,"
        " updated_at INTEGER)");
    mDb.sql().exec("CREATE INDEX IF NOT EXISTS models_owner ON models(owner_id)");
}

std::int64_t ModelStore::create(std::int64_t ownerId, const std::string& name,
                                const std::string& hmf, bool isExample)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement insert(mDb.sql(),
                             "INSERT INTO models(owner_id, name, hmf, is_example, created_at,"
                             " updated_at) VALUES(?, ?, ?, ?, ?, ?)");
    insert.bind(1, ownerId);
    insert.bind(2, name);
    insert.bind(3, hmf);
    insert.bind(4, isExample ? 1 : 0);
    insert.bind(5, now);
    insert.bind(6, now);
    insert.exec();
    return mDb.sql().getLastInsertRowid();
}

std::optional<ModelSummary> ModelStore::summary(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), std::string(kSummaryColumns) + " WHERE m.id = ?");
    q.bind(1, id);
    if (!q.executeStep()) return std::nullopt;
    return readSummary(q);
}

std::optional<std::string> ModelStore::hmf(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT hmf FROM models WHERE id = ?");
    q.bind(1, id);
    if (!q.executeStep()) return std::nullopt;
    return q.getColumn(0).getString();
}

bool ModelStore::update(std::int64_t id, const std::optional<std::string>& name,
                        const std::optional<std::string>& hmf)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    std::lock_guard lock(mDb.mutex());
    // COALESCE keeps a field whose new value is NULL (not given).
    SQLite::Statement update(mDb.sql(),
                             "UPDATE models SET name = COALESCE(?, name), hmf = COALESCE(?, hmf),"
                             " updated_at = ? WHERE id = ?");
    if (name) update.bind(1, *name); else update.bind(1);
    if (hmf) update.bind(2, *hmf); else update.bind(2);
    update.bind(3, now);
    update.bind(4, id);
    return update.exec() > 0;
}

bool ModelStore::remove(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    const bool removed = mDb.freeingSpace([&] {
        SQLite::Statement remove(mDb.sql(), "DELETE FROM models WHERE id = ?");
        remove.bind(1, id);
        return remove.exec() > 0;
    });
    mDb.restoreReserve();
    return removed;
}

std::vector<ModelSummary> ModelStore::listVisibleTo(const User& who)
{
    // Filtered here with the access policy rather than in SQL, so the rule has one home.
    // Summaries carry no model text, so reading them all stays cheap at classroom scale.
    std::vector<ModelSummary> visible;
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), std::string(kSummaryColumns) + " ORDER BY m.id");
    while (q.executeStep()) {
        ModelSummary s = readSummary(q);
        if (canRead(who, s.ownerId, s.ownerRole, s.isExample)) visible.push_back(std::move(s));
    }
    return visible;
}

} // namespace tlmhub::server
