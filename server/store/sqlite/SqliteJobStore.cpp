#include "server/jobs/JobStore.h"

#include "server/store/ResultBlob.h"

#include <SQLiteCpp/Statement.h>
#include <SQLiteCpp/Transaction.h>

namespace tlmhub::server {

namespace {

constexpr const char* kInfoColumns =
    "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"
    " finished_at, steps, start, step, stop, log_samples FROM jobs";

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
    return j;
}

} // namespace

JobStore::JobStore(Database& db) : mDb(db)
{
    std::lock_guard lock(mDb.mutex());
    // Owners and models are not foreign keys: a job's record outlives a deleted model, and
    // this table does not depend on which store created its tables first.
    mDb.sql().exec(
        "CREATE TABLE IF NOT EXISTS jobs ("
        " id INTEGER PRIMARY KEY AUTOINCREMENT,"
        " owner_id INTEGER NOT NULL,"
        " model_id INTEGER,"
        " state TEXT NOT NULL,"
        " progress REAL NOT NULL DEFAULT 0,"
        " error TEXT NOT NULL DEFAULT '',"
        " created_at INTEGER NOT NULL,"
        " started_at INTEGER NOT NULL DEFAULT 0,"
        " finished_at INTEGER NOT NULL DEFAULT 0,"
        " steps INTEGER NOT NULL DEFAULT 0,"
        " start REAL NOT NULL, step REAL NOT NULL, stop REAL NOT NULL,"
        " log_samples INTEGER NOT NULL,"
        " request TEXT NOT NULL)");
    mDb.sql().exec("CREATE INDEX IF NOT EXISTS jobs_owner ON jobs(owner_id)");
    mDb.sql().exec("CREATE INDEX IF NOT EXISTS jobs_state ON jobs(state)");
    mDb.sql().exec(
        "CREATE TABLE IF NOT EXISTS job_results ("
        " job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
        " data BLOB NOT NULL)");
}

std::int64_t JobStore::create(const JobRequest& request, const JobInfo& resolved)
{
    const std::string requestJson = request.toJson().dump();
    const auto now = static_cast<std::int64_t>(unixNow());
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement insert(mDb.sql(),
                             "INSERT INTO jobs(owner_id, model_id, state, created_at, steps, start,"
                             " step, stop, log_samples, request) VALUES(?,?,?,?,?,?,?,?,?,?)");
    insert.bind(1, request.ownerId);
    if (request.modelId) insert.bind(2, *request.modelId);
    else insert.bind(2);
    insert.bind(3, jobStateName(JobState::Queued));
    insert.bind(4, now);
    insert.bind(5, static_cast<std::int64_t>(resolved.steps));
    insert.bind(6, resolved.start);
    insert.bind(7, resolved.step);
    insert.bind(8, resolved.stop);
    insert.bind(9, static_cast<std::int64_t>(resolved.logSamples));
    insert.bind(10, requestJson);
    insert.exec();
    return mDb.sql().getLastInsertRowid();
}

std::optional<JobInfo> JobStore::info(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), std::string(kInfoColumns) + " WHERE id = ?");
    q.bind(1, id);
    if (!q.executeStep()) return std::nullopt;
    return readInfo(q);
}

std::optional<JobRequest> JobStore::request(std::int64_t id)
{
    std::string text;
    {
        std::lock_guard lock(mDb.mutex());
        SQLite::Statement q(mDb.sql(), "SELECT request FROM jobs WHERE id = ?");
        q.bind(1, id);
        if (!q.executeStep()) return std::nullopt;
        text = q.getColumn(0).getString();
    }
    const auto json = nlohmann::json::parse(text, nullptr, false);
    JobRequest r;
    if (json.is_discarded() || !JobRequest::fromJson(json, r)) return std::nullopt;
    return r;
}

std::vector<JobInfo> JobStore::list(const std::string& where, std::int64_t value, const char* order)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), std::string(kInfoColumns) + where + " ORDER BY id " + order);
    if (!where.empty()) q.bind(1, value);
    std::vector<JobInfo> out;
    while (q.executeStep()) out.push_back(readInfo(q));
    return out;
}

std::vector<JobInfo> JobStore::listForOwner(std::int64_t ownerId)
{
    return list(" WHERE owner_id = ?", ownerId, "DESC");
}

std::vector<JobInfo> JobStore::listAll() { return list("", 0, "DESC"); }

std::vector<JobInfo> JobStore::listInState(JobState state)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), std::string(kInfoColumns) + " WHERE state = ? ORDER BY id ASC");
    q.bind(1, jobStateName(state));
    std::vector<JobInfo> out;
    while (q.executeStep()) out.push_back(readInfo(q));
    return out;
}

bool JobStore::markRunning(std::int64_t id)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(),
                        "UPDATE jobs SET state = 'running', started_at = ?, progress = 0"
                        " WHERE id = ? AND state = 'queued'");
    q.bind(1, now);
    q.bind(2, id);
    return q.exec() == 1;
}

void JobStore::setProgress(std::int64_t id, double progress)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "UPDATE jobs SET progress = ? WHERE id = ? AND state = 'running'");
    q.bind(1, progress);
    q.bind(2, id);
    q.exec();
}

bool JobStore::finish(std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
                      const std::string* resultBlob)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    std::lock_guard lock(mDb.mutex());
    SQLite::Transaction transaction(mDb.sql());
    SQLite::Statement q(mDb.sql(),
                        "UPDATE jobs SET state = ?, error = ?, steps = ?, finished_at = ?,"
                        " progress = CASE WHEN ? THEN 1 ELSE progress END"
                        " WHERE id = ? AND state IN ('queued', 'running')");
    q.bind(1, jobStateName(state));
    q.bind(2, error);
    q.bind(3, static_cast<std::int64_t>(steps));
    q.bind(4, now);
    q.bind(5, state == JobState::Done ? 1 : 0);
    q.bind(6, id);
    if (q.exec() != 1) return false;
    if (resultBlob) {
        SQLite::Statement insert(mDb.sql(), "INSERT OR REPLACE INTO job_results(job_id, data) VALUES(?, ?)");
        insert.bind(1, id);
        insert.bindNoCopy(2, resultBlob->data(), static_cast<int>(resultBlob->size()));
        insert.exec();
    }
    transaction.commit();
    return true;
}

int JobStore::markRunningInterrupted()
{
    const auto now = static_cast<std::int64_t>(unixNow());
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(),
                        "UPDATE jobs SET state = 'interrupted', finished_at = ?,"
                        " error = 'the server stopped while the job was running'"
                        " WHERE state = 'running'");
    q.bind(1, now);
    return q.exec();
}

std::optional<ResultTable> JobStore::result(std::int64_t id, const std::vector<std::string>& variables)
{
    std::string blob;
    {
        std::lock_guard lock(mDb.mutex());
        SQLite::Statement q(mDb.sql(), "SELECT data FROM job_results WHERE job_id = ?");
        q.bind(1, id);
        if (!q.executeStep()) return std::nullopt;
        blob = q.getColumn(0).getString();
    }
    return decodeResult(blob, variables);
}

bool JobStore::hasResult(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT 1 FROM job_results WHERE job_id = ?");
    q.bind(1, id);
    return q.executeStep();
}

bool JobStore::remove(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    const bool removed = mDb.freeingSpace([&] {
        SQLite::Transaction transaction(mDb.sql());
        SQLite::Statement results(mDb.sql(), "DELETE FROM job_results WHERE job_id = ?");
        results.bind(1, id);
        results.exec();
        SQLite::Statement q(mDb.sql(), "DELETE FROM jobs WHERE id = ?");
        q.bind(1, id);
        const bool done = q.exec() == 1;
        transaction.commit();
        return done;
    });
    mDb.restoreReserve();
    return removed;
}

int JobStore::removeFinishedBefore(std::int64_t unixSeconds)
{
    const char* finished = "state IN ('done', 'failed', 'cancelled', 'interrupted') AND finished_at < ?";
    std::lock_guard lock(mDb.mutex());
    SQLite::Transaction transaction(mDb.sql());
    SQLite::Statement results(mDb.sql(), std::string("DELETE FROM job_results WHERE job_id IN"
                                                     " (SELECT id FROM jobs WHERE ") + finished + ")");
    results.bind(1, unixSeconds);
    results.exec();
    SQLite::Statement jobs(mDb.sql(), std::string("DELETE FROM jobs WHERE ") + finished);
    jobs.bind(1, unixSeconds);
    const int removed = jobs.exec();
    transaction.commit();
    return removed;
}

std::size_t JobStore::storedBytes(std::int64_t ownerId)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(),
                        "SELECT COALESCE(SUM(length(r.data)), 0) FROM job_results r"
                        " JOIN jobs j ON j.id = r.job_id WHERE j.owner_id = ?");
    q.bind(1, ownerId);
    return q.executeStep() ? static_cast<std::size_t>(q.getColumn(0).getInt64()) : 0;
}

} // namespace tlmhub::server
