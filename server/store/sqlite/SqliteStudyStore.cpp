#include "server/store/UnixTime.h"
#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>
#include <sqlite3.h>

#include <algorithm>

namespace tlmhub::server {

namespace {

// The columns readInfo reads, in its order; one full text per query so each is prepared once.
#define TLMHUB_STUDY_INFO                                                                       \
    "SELECT id, owner_id, model_id, kind, name, state, runs_total, runs_done, runs_failed,"    \
    " error, created_at, started_at, finished_at, summary FROM studies"
constexpr const char* kInfoById = TLMHUB_STUDY_INFO " WHERE id = ?";
constexpr const char* kInfoByOwner = TLMHUB_STUDY_INFO " WHERE owner_id = ? ORDER BY id DESC";
constexpr const char* kInfoByState = TLMHUB_STUDY_INFO " WHERE state = ? ORDER BY id ASC";
#undef TLMHUB_STUDY_INFO

StudyInfo readInfo(SQLite::Statement& q)
{
    StudyInfo s;
    s.id = q.getColumn(0).getInt64();
    s.ownerId = q.getColumn(1).getInt64();
    if (!q.getColumn(2).isNull()) s.modelId = q.getColumn(2).getInt64();
    s.kind = q.getColumn(3).getString();
    s.name = q.getColumn(4).getString();
    jobStateFromName(q.getColumn(5).getString(), s.state);
    s.runsTotal = q.getColumn(6).getInt64();
    s.runsDone = q.getColumn(7).getInt64();
    s.runsFailed = q.getColumn(8).getInt64();
    s.error = q.getColumn(9).getString();
    s.createdAt = q.getColumn(10).getInt64();
    s.startedAt = q.getColumn(11).getInt64();
    s.finishedAt = q.getColumn(12).getInt64();
    s.summary = q.getColumn(13).getString();
    return s;
}

std::vector<StudyInfo> readInfos(SqliteConnection::Statement& q)
{
    std::vector<StudyInfo> out;
    while (q->executeStep()) out.push_back(readInfo(*q));
    return out;
}

int countActive(SqliteConnection& c, std::int64_t ownerId)
{
    auto q = c.prepared("SELECT COUNT(*) FROM studies WHERE owner_id = ? AND state IN ('queued', 'running')");
    q->bind(1, ownerId);
    q->executeStep();
    return q->getColumn(0).getInt();
}

// Studies held by no node that answers: none, or one not seen since ?1 (ms), other than ?2.
#define TLMHUB_ORPHANED                                                                                   \
    " (node IS NULL OR (node <> ?2 AND node NOT IN (SELECT id FROM nodes WHERE last_seen >= ?1)))"

} // namespace

std::optional<std::int64_t> SqliteStudyStore::create(std::int64_t ownerId, std::optional<std::int64_t> modelId,
                                                      const std::string& kind, const std::string& name,
                                                      const std::string& request, std::int64_t runsTotal,
                                                      const std::string& node, int maxActive)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        // IMMEDIATE: every node writing to the file waits for this count and insert.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        if (countActive(c, ownerId) >= maxActive) return std::nullopt;
        auto insert = c.prepared("INSERT INTO studies(owner_id, model_id, kind, name, state, runs_total,"
                                 " created_at, request, node) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)");
        insert->bind(1, ownerId);
        if (modelId) insert->bind(2, *modelId);
        else insert->bind(2);
        insert->bind(3, kind);
        insert->bind(4, name);
        insert->bind(5, jobStateName(JobState::Queued));
        insert->bind(6, runsTotal);
        insert->bind(7, now);
        insert->bind(8, request);
        insert->bind(9, node);
        try {
            insert->exec();
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;
            throw;
        }
        const std::int64_t id = c.db().getLastInsertRowid();
        transaction.commit();
        return id;
    });
}

std::optional<StudyInfo> SqliteStudyStore::info(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<StudyInfo> {
        auto q = c.prepared(kInfoById);
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readInfo(*q);
    });
}

std::optional<std::string> SqliteStudyStore::request(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT request FROM studies WHERE id = ?");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

std::vector<StudyInfo> SqliteStudyStore::listForOwner(std::int64_t ownerId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kInfoByOwner);
        q->bind(1, ownerId);
        return readInfos(q);
    });
}

std::vector<StudyInfo> SqliteStudyStore::listInState(JobState state)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kInfoByState);
        q->bind(1, jobStateName(state));
        return readInfos(q);
    });
}

int SqliteStudyStore::activeCount(std::int64_t ownerId)
{
    return mDb.run([&](SqliteConnection& c) { return countActive(c, ownerId); });
}

bool SqliteStudyStore::markRunning(std::int64_t id, const std::string& node)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE studies SET state = 'running', started_at = ?"
                            " WHERE id = ? AND state = 'queued' AND node = ?");
        q->bind(1, now);
        q->bind(2, id);
        q->bind(3, node);
        return q->exec() == 1;
    });
}

bool SqliteStudyStore::addRun(std::int64_t studyId, const StudyRun& run, const std::string* resultBlob)
{
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto count = c.prepared("UPDATE studies SET runs_done = runs_done + ?, runs_failed = runs_failed + ?"
                                    " WHERE id = ? AND state = 'running'");
            count->bind(1, run.ok ? 1 : 0);
            count->bind(2, run.ok ? 0 : 1);
            count->bind(3, studyId);
            if (count->exec() != 1) return false;
        }
        // A run index taken already inserts nothing; the count above is rolled back with it.
        auto insert = c.prepared("INSERT INTO study_runs(study_id, run_index, ok, parameters, outputs, error, result, node)"
                                 " VALUES(?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT DO NOTHING");
        insert->bind(1, studyId);
        insert->bind(2, run.index);
        insert->bind(3, run.ok ? 1 : 0);
        insert->bind(4, run.parameters);
        insert->bind(5, run.outputs);
        insert->bind(6, run.error);
        if (resultBlob) insert->bindNoCopy(7, resultBlob->data(), static_cast<int>(resultBlob->size()));
        else insert->bind(7);
        insert->bind(8, run.node);
        if (insert->exec() != 1) return false;
        transaction.commit();
        return true;
    });
}

void SqliteStudyStore::setSummary(std::int64_t id, const std::string& summary)
{
    mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE studies SET summary = ? WHERE id = ? AND state IN ('queued', 'running')");
        q->bind(1, summary);
        q->bind(2, id);
        q->exec();
    });
}

bool SqliteStudyStore::finish(std::int64_t id, JobState state, const std::string& error, const std::string& summary)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE studies SET state = ?, error = ?, summary = ?, finished_at = ?"
                            " WHERE id = ? AND state IN ('queued', 'running')");
        q->bind(1, jobStateName(state));
        q->bind(2, error);
        q->bind(3, summary);
        q->bind(4, now);
        q->bind(5, id);
        return q->exec() == 1;
    });
}

std::vector<StudyInfo> SqliteStudyStore::adoptOrphans(const std::string& node, std::chrono::milliseconds within)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    const std::int64_t since = unixNowMillis() - within.count();
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto interrupt = c.prepared("UPDATE studies SET state = 'interrupted', finished_at = ?3,"
                                        " error = 'its server stopped while the study was running'"
                                        " WHERE state = 'running' AND" TLMHUB_ORPHANED);
            interrupt->bind(1, since);
            interrupt->bind(2, node);
            interrupt->bind(3, now);
            interrupt->exec();
        }
        auto adopt = c.prepared("UPDATE studies SET node = ?2 WHERE state = 'queued' AND" TLMHUB_ORPHANED " RETURNING id");
        adopt->bind(1, since);
        adopt->bind(2, node);
        std::vector<std::int64_t> ids;
        while (adopt->executeStep()) ids.push_back(adopt->getColumn(0).getInt64());
        adopt->reset();
        std::sort(ids.begin(), ids.end());
        std::vector<StudyInfo> adopted;
        for (const std::int64_t id : ids) {
            auto q = c.prepared(kInfoById);
            q->bind(1, id);
            if (q->executeStep()) adopted.push_back(readInfo(*q));
        }
        transaction.commit();
        return adopted;
    });
}
#undef TLMHUB_ORPHANED

void SqliteStudyStore::releaseQueued(const std::string& node)
{
    mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE studies SET node = NULL WHERE node = ? AND state = 'queued'");
        q->bind(1, node);
        q->exec();
    });
}

bool SqliteStudyStore::reopen(std::int64_t id, const std::string& node, int maxActive)
{
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        auto owner = c.prepared("SELECT owner_id FROM studies WHERE id = ?");
        owner->bind(1, id);
        if (!owner->executeStep()) return false;
        const std::int64_t ownerId = owner->getColumn(0).getInt64();
        owner->reset();
        if (countActive(c, ownerId) >= maxActive) return false;
        auto q = c.prepared("UPDATE studies SET state = 'queued', error = '', finished_at = 0, node = ?"
                            " WHERE id = ? AND state IN ('interrupted', 'cancelled')");
        q->bind(1, node);
        q->bind(2, id);
        if (q->exec() != 1) return false;
        transaction.commit();
        return true;
    });
}

std::vector<StudyRun> SqliteStudyStore::runs(std::int64_t studyId, std::int64_t fromIndex, std::size_t limit)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT run_index, ok, parameters, outputs, error, result IS NOT NULL, node FROM study_runs"
                            " WHERE study_id = ? AND run_index >= ? ORDER BY run_index LIMIT ?");
        q->bind(1, studyId);
        q->bind(2, fromIndex);
        q->bind(3, static_cast<std::int64_t>(limit));
        std::vector<StudyRun> out;
        while (q->executeStep())
            out.push_back(StudyRun{q->getColumn(0).getInt64(), q->getColumn(1).getInt() != 0,
                                   q->getColumn(2).getString(), q->getColumn(3).getString(),
                                   q->getColumn(4).getString(), q->getColumn(5).getInt() != 0,
                                   q->getColumn(6).getString()});
        return out;
    });
}

std::optional<std::string> SqliteStudyStore::runResult(std::int64_t studyId, std::int64_t index)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT result FROM study_runs WHERE study_id = ? AND run_index = ? AND result IS NOT NULL");
        q->bind(1, studyId);
        q->bind(2, index);
        if (!q->executeStep()) return std::nullopt;
        const SQLite::Column data = q->getColumn(0);
        return std::string(static_cast<const char*>(data.getBlob()), static_cast<std::size_t>(data.getBytes()));
    });
}

std::size_t SqliteStudyStore::storedBytes(std::int64_t ownerId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT COALESCE(SUM(length(r.result)), 0) FROM study_runs r"
                            " JOIN studies s ON s.id = r.study_id WHERE s.owner_id = ?");
        q->bind(1, ownerId);
        return q->executeStep() ? static_cast<std::size_t>(q->getColumn(0).getInt64()) : std::size_t(0);
    });
}

bool SqliteStudyStore::remove(std::int64_t id)
{
    // The runs go with their study (ON DELETE CASCADE), in the same statement.
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM studies WHERE id = ?");
        q->bind(1, id);
        return q->exec() == 1;
    });
    mDb.restoreReserve();
    return removed;
}

} // namespace tlmhub::server
