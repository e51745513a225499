#include "server/store/StoreError.h"
#include "server/store/UnixTime.h"
#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>

namespace tlmhub::server {

namespace {

// The columns readInfo reads, in its order; one full text per query so each is prepared once.
#define TLMHUB_JOB_COLUMNS                                                                      \
    "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"           \
    " finished_at, steps, start, step, stop, log_samples, name, pinned, results_dropped_at"
#define TLMHUB_JOB_INFO TLMHUB_JOB_COLUMNS " FROM jobs"
constexpr const char* kInfoById = TLMHUB_JOB_INFO " WHERE id = ?";
// The history of a model: with the overrides (column 17) and the values used (18), and for one
// owner (?2 not null) or all, below an id (?3 not null); ?4 rows.
constexpr const char* kHistory =
    TLMHUB_JOB_COLUMNS ", json_extract(request, '$.parameters'),"
    " json_extract(request, '$.used_parameters') FROM jobs"
    " WHERE model_id = ?1 AND (?2 IS NULL OR owner_id = ?2) AND (?3 IS NULL OR id < ?3)"
    " ORDER BY id DESC LIMIT ?4";
constexpr const char* kInfoByOwner = TLMHUB_JOB_INFO " WHERE owner_id = ? ORDER BY id DESC";
constexpr const char* kInfoAll = TLMHUB_JOB_INFO " ORDER BY id DESC";
constexpr const char* kInfoByState = TLMHUB_JOB_INFO " WHERE state = ? ORDER BY id ASC";
#undef TLMHUB_JOB_INFO
#undef TLMHUB_JOB_COLUMNS

// Finished states, as in isFinished().
constexpr const char* kDeleteOldResults =
    "DELETE FROM job_results WHERE job_id IN (SELECT id FROM jobs WHERE"
    " state IN ('done', 'failed', 'cancelled', 'interrupted', 'dead') AND finished_at < ? AND pinned = 0)";
constexpr const char* kDeleteOldJobs =
    "DELETE FROM jobs WHERE state IN ('done', 'failed', 'cancelled', 'interrupted', 'dead') AND finished_at < ?"
    " AND pinned = 0";
// A model's finished unpinned jobs with results, but the newest ?2, are marked (at ?3); then
// the results of its marked jobs go.
constexpr const char* kMarkResultsDropped =
    "UPDATE jobs SET results_dropped_at = ?3 WHERE id IN (SELECT id FROM jobs WHERE model_id = ?1 AND pinned = 0"
    " AND results_dropped_at = 0 AND state IN ('done', 'failed', 'cancelled', 'interrupted', 'dead')"
    " ORDER BY id DESC LIMIT -1 OFFSET ?2)";
constexpr const char* kDeleteDroppedResults =
    "DELETE FROM job_results WHERE job_id IN (SELECT id FROM jobs WHERE model_id = ? AND results_dropped_at > 0)";

JobInfo readInfo(SQLite::Statement& q)
{
    JobInfo j;
    j.id = q.getColumn(0).getInt64();
    j.ownerId = q.getColumn(1).getInt64();
    if (!q.getColumn(2).isNull()) j.modelId = q.getColumn(2).getInt64();
    jobStateFromName(q.getColumn(3).getString(), j.state);
    j.progress = q.getColumn(4).getDouble();
    j.error = q.getColumn(5).getString();
    j.createdAt = q.getColumn(6).getInt64();
    j.startedAt = q.getColumn(7).getInt64();
    j.finishedAt = q.getColumn(8).getInt64();
    j.steps = static_cast<std::uint64_t>(q.getColumn(9).getInt64());
    j.start = q.getColumn(10).getDouble();
    j.step = q.getColumn(11).getDouble();
    j.stop = q.getColumn(12).getDouble();
    j.logSamples = static_cast<std::size_t>(q.getColumn(13).getInt64());
    j.name = q.getColumn(14).getString();
    j.pinned = q.getColumn(15).getInt() != 0;
    j.resultsDropped = q.getColumn(16).getInt64() != 0;
    return j;
}

std::vector<JobInfo> readInfos(SqliteConnection::Statement& q)
{
    std::vector<JobInfo> out;
    while (q->executeStep()) out.push_back(readInfo(*q));
    return out;
}

} // namespace

namespace {

std::int64_t insertQueuedJob(SqliteConnection& c, const JobRequest& request, const JobInfo& resolved)
{
    auto insert = c.prepared("INSERT INTO jobs(owner_id, model_id, state, created_at, steps, start,"
                             " step, stop, log_samples, request) VALUES(?,?,?,?,?,?,?,?,?,?)");
    insert->bind(1, request.ownerId);
    if (request.modelId) insert->bind(2, *request.modelId);
    else insert->bind(2);
    insert->bind(3, jobStateName(JobState::Queued));
    insert->bind(4, static_cast<std::int64_t>(unixNow()));
    insert->bind(5, static_cast<std::int64_t>(resolved.steps));
    insert->bind(6, resolved.start);
    insert->bind(7, resolved.step);
    insert->bind(8, resolved.stop);
    insert->bind(9, static_cast<std::int64_t>(resolved.logSamples));
    insert->bind(10, request.toJson().dump());
    insert->exec();
    return static_cast<std::int64_t>(c.db().getLastInsertRowid());
}

bool markJobRunning(SqliteConnection& c, std::int64_t id, std::int64_t now)
{
    auto q = c.prepared("UPDATE jobs SET state = 'running', started_at = ?, progress = 0"
                        " WHERE id = ? AND state = 'queued'");
    q->bind(1, now);
    q->bind(2, id);
    return q->exec() == 1;
}

// finish's statements; the caller holds the transaction.
bool finishJob(SqliteConnection& c, std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
               std::int64_t now, const std::string* resultBlob)
{
    {
        auto q = c.prepared("UPDATE jobs SET state = ?, error = ?, steps = ?, finished_at = ?,"
                            " progress = CASE WHEN ? THEN 1 ELSE progress END"
                            " WHERE id = ? AND state IN ('queued', 'running')");
        q->bind(1, jobStateName(state));
        q->bind(2, error);
        q->bind(3, static_cast<std::int64_t>(steps));
        q->bind(4, now);
        q->bind(5, state == JobState::Done ? 1 : 0);
        q->bind(6, id);
        if (q->exec() != 1) return false;
    }
    if (resultBlob) {
        auto insert = c.prepared("INSERT OR REPLACE INTO job_results(job_id, data) VALUES(?, ?)");
        insert->bind(1, id);
        insert->bindNoCopy(2, resultBlob->data(), static_cast<int>(resultBlob->size()));
        insert->exec();
    }
    return true;
}

bool labelJob(SqliteConnection& c, std::int64_t id, const std::optional<std::string>& name,
              std::optional<bool> pinned)
{
    auto q = c.prepared("UPDATE jobs SET name = COALESCE(?, name), pinned = COALESCE(?, pinned) WHERE id = ?");
    if (name) q->bind(1, *name);
    else q->bind(1);
    if (pinned) q->bind(2, *pinned ? 1 : 0);
    else q->bind(2);
    q->bind(3, id);
    return q->exec() == 1;
}

} // namespace

std::int64_t SqliteJobStore::create(const JobRequest& request, const JobInfo& resolved)
{
    return mDb.run([&](SqliteConnection& c) { return insertQueuedJob(c, request, resolved); });
}

JobStore::Admission SqliteJobStore::createWithinQueueLimit(const JobRequest& request, const JobInfo& resolved,
                                                           int maxQueued)
{
    return mDb.run([&](SqliteConnection& c) {
        // IMMEDIATE: the write lock before the count, so no other submit counts in between.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        Admission admission;
        {
            auto count = c.prepared("SELECT COUNT(*) FROM jobs WHERE owner_id = ? AND state = 'queued'");
            count->bind(1, request.ownerId);
            count->executeStep();
            admission.queued = count->getColumn(0).getInt();
        }
        if (admission.queued >= maxQueued) return admission;
        admission.id = insertQueuedJob(c, request, resolved);
        transaction.commit();
        return admission;
    });
}

std::int64_t SqliteJobStore::createFinished(const JobRequest& request, const JobInfo& resolved, std::uint64_t steps,
                                           const std::string& resultBlob, const std::string& name)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        // create, markRunning, finish and label in one transaction: no claim sees it queued.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        const std::int64_t id = insertQueuedJob(c, request, resolved);
        if (!markJobRunning(c, id, now) || !finishJob(c, id, JobState::Done, "", steps, now, &resultBlob) ||
            !labelJob(c, id, name, std::nullopt))
            throw StoreError(StoreErrc::Internal, "the finished job could not be stored");
        transaction.commit();
        return id;
    });
}

std::optional<JobInfo> SqliteJobStore::info(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<JobInfo> {
        auto q = c.prepared(kInfoById);
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readInfo(*q);
    });
}

std::optional<std::string> SqliteJobStore::requestText(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT request FROM jobs WHERE id = ?");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

std::vector<JobInfo> SqliteJobStore::listForOwner(std::int64_t ownerId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kInfoByOwner);
        q->bind(1, ownerId);
        return readInfos(q);
    });
}

std::vector<JobInfo> SqliteJobStore::listForModel(std::int64_t modelId, std::optional<std::int64_t> ownerId,
                                                 std::optional<std::int64_t> beforeId, int limit)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kHistory);
        q->bind(1, modelId);
        if (ownerId) q->bind(2, *ownerId);
        else q->bind(2);
        if (beforeId) q->bind(3, *beforeId);
        else q->bind(3);
        q->bind(4, limit);
        std::vector<JobInfo> out;
        while (q->executeStep()) {
            JobInfo job = readInfo(*q);
            job.parameters = parameterOverrides(q->getColumn(17).isNull() ? "" : q->getColumn(17).getString());
            if (!q->getColumn(18).isNull()) job.usedParameters = parameterOverrides(q->getColumn(18).getString());
            out.push_back(std::move(job));
        }
        return out;
    });
}

bool SqliteJobStore::label(std::int64_t id, const std::optional<std::string>& name, std::optional<bool> pinned)
{
    return mDb.run([&](SqliteConnection& c) { return labelJob(c, id, name, pinned); });
}

int SqliteJobStore::dropOldResults(std::int64_t modelId, int keep)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    const int dropped = mDb.runFreeingSpace([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        auto mark = c.prepared(kMarkResultsDropped);
        mark->bind(1, modelId);
        mark->bind(2, keep);
        mark->bind(3, now);
        const int marked = mark->exec();
        auto results = c.prepared(kDeleteDroppedResults);
        results->bind(1, modelId);
        results->exec();
        transaction.commit();
        return marked;
    });
    mDb.restoreReserve();
    return dropped;
}

bool SqliteJobStore::dropResults(std::int64_t id)
{
    const bool dropped = mDb.runFreeingSpace([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        auto mark = c.prepared("UPDATE jobs SET results_dropped_at = ? WHERE id = ? AND results_dropped_at = 0"
                               " AND state IN ('done', 'failed', 'cancelled', 'interrupted', 'dead')");
        mark->bind(1, static_cast<std::int64_t>(unixNow()));
        mark->bind(2, id);
        if (mark->exec() != 1) return false;
        auto results = c.prepared("DELETE FROM job_results WHERE job_id = ?");
        results->bind(1, id);
        results->exec();
        transaction.commit();
        return true;
    });
    mDb.restoreReserve();
    return dropped;
}

std::vector<JobInfo> SqliteJobStore::listAll()
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kInfoAll);
        return readInfos(q);
    });
}

std::vector<JobInfo> SqliteJobStore::listInState(JobState state)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kInfoByState);
        q->bind(1, jobStateName(state));
        return readInfos(q);
    });
}

bool SqliteJobStore::markRunning(std::int64_t id)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) { return markJobRunning(c, id, now); });
}

void SqliteJobStore::setProgress(std::int64_t id, double progress)
{
    mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE jobs SET progress = ? WHERE id = ? AND state = 'running'");
        q->bind(1, progress);
        q->bind(2, id);
        q->exec();
    });
}

bool SqliteJobStore::finish(std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
                            const std::string* resultBlob)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        if (!finishJob(c, id, state, error, steps, now, resultBlob)) return false;
        transaction.commit();
        return true;
    });
}

bool SqliteJobStore::remove(std::int64_t id)
{
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto results = c.prepared("DELETE FROM job_results WHERE job_id = ?");
            results->bind(1, id);
            results->exec();
        }
        auto q = c.prepared("DELETE FROM jobs WHERE id = ?");
        q->bind(1, id);
        const bool done = q->exec() == 1;
        transaction.commit();
        return done;
    });
    mDb.restoreReserve();
    return removed;
}

int SqliteJobStore::removeFinishedBefore(std::int64_t unixSeconds)
{
    const int removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto results = c.prepared(kDeleteOldResults);
            results->bind(1, unixSeconds);
            results->exec();
        }
        auto jobs = c.prepared(kDeleteOldJobs);
        jobs->bind(1, unixSeconds);
        const int count = jobs->exec();
        transaction.commit();
        return count;
    });
    mDb.restoreReserve();
    return removed;
}

} // namespace tlmhub::server
