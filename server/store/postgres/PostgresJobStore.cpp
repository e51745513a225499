#include "server/store/StoreError.h"
#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

constexpr PgStatement kCreate{"jobs_create",
                              "INSERT INTO jobs(owner_id, model_id, state, created_at, steps, start, step, stop,"
                              " log_samples, request) VALUES($1, $2, $3, $4, $5, $6, $7, $8, $9, $10) RETURNING id"};
// Submits of one owner take turns through this lock (the two-key form: a key space apart
// from the one-key locks of claims and migrations), so their counts and inserts never
// interleave. The class is "tlm\3"; the owner's id is folded into an int.
constexpr int kAdmissionLockClass = 0x746c6d03;
constexpr PgStatement kAdmissionLock{"jobs_admission_lock",
                                     "SELECT pg_advisory_xact_lock($1::int, ($2 % 2147483647)::int)"};
constexpr PgStatement kQueuedCount{"jobs_queued_count",
                                   "SELECT COUNT(*) FROM jobs WHERE owner_id = $1 AND state = 'queued'"};
constexpr PgStatement kInfo{"jobs_info",
                            "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"
                            " finished_at, steps, start, step, stop, log_samples, name, pinned, results_dropped_at FROM jobs WHERE id = $1"};
constexpr PgStatement kRequest{"jobs_request", "SELECT request FROM jobs WHERE id = $1"};
constexpr PgStatement kListForOwner{"jobs_list_for_owner",
                                    "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"
                                    " finished_at, steps, start, step, stop, log_samples, name, pinned, results_dropped_at FROM jobs"
                                    " WHERE owner_id = $1 ORDER BY id DESC"};
// The history of a model: with the overrides (column 17) and the values used (18), for one
// owner ($2 not null) or all, below an id ($3 not null); $4 rows. The request is parsed once.
constexpr PgStatement kListForModel{"jobs_list_for_model",
                                    "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"
                                    " finished_at, steps, start, step, stop, log_samples, name, pinned,"
                                    " results_dropped_at, (r.j -> 'parameters')::text, (r.j -> 'used_parameters')::text"
                                    " FROM jobs, LATERAL (SELECT request::jsonb AS j) r"
                                    " WHERE model_id = $1 AND ($2::bigint IS NULL OR owner_id = $2)"
                                    " AND ($3::bigint IS NULL OR id < $3) ORDER BY id DESC LIMIT $4"};
constexpr PgStatement kLabel{"jobs_label",
                             "UPDATE jobs SET name = COALESCE($1, name), pinned = COALESCE($2::boolean, pinned)"
                             " WHERE id = $3"};
// A model's finished unpinned jobs with results, but the newest $2, lose them; their rows stay.
constexpr PgStatement kDropOldResults{
    "jobs_drop_old_results",
    "WITH dropped AS (UPDATE jobs SET results_dropped_at = $3 WHERE id IN ("
    " SELECT id FROM jobs WHERE model_id = $1 AND NOT pinned AND results_dropped_at = 0"
    " AND state IN ('done', 'failed', 'cancelled', 'interrupted', 'dead') ORDER BY id DESC OFFSET $2)"
    " RETURNING id),"
    " gone AS (DELETE FROM job_results WHERE job_id IN (SELECT id FROM dropped))"
    " SELECT COUNT(*) FROM dropped"};
constexpr PgStatement kDropResults{
    "jobs_drop_results",
    "WITH dropped AS (UPDATE jobs SET results_dropped_at = $2 WHERE id = $1 AND results_dropped_at = 0"
    " AND state IN ('done', 'failed', 'cancelled', 'interrupted', 'dead') RETURNING id),"
    " gone AS (DELETE FROM job_results WHERE job_id IN (SELECT id FROM dropped))"
    " SELECT COUNT(*) FROM dropped"};
constexpr PgStatement kListAll{"jobs_list_all",
                               "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"
                               " finished_at, steps, start, step, stop, log_samples, name, pinned, results_dropped_at FROM jobs ORDER BY id DESC"};
constexpr PgStatement kListInState{"jobs_list_in_state",
                                   "SELECT id, owner_id, model_id, state, progress, error, created_at, started_at,"
                                   " finished_at, steps, start, step, stop, log_samples, name, pinned, results_dropped_at FROM jobs"
                                   " WHERE state = $1 ORDER BY id ASC"};
constexpr PgStatement kMarkRunning{"jobs_mark_running",
                                   "UPDATE jobs SET state = 'running', started_at = $1, progress = 0"
                                   " WHERE id = $2 AND state = 'queued'"};
constexpr PgStatement kSetProgress{"jobs_set_progress",
                                   "UPDATE jobs SET progress = $1 WHERE id = $2 AND state = 'running'"};
constexpr PgStatement kFinish{"jobs_finish",
                              "UPDATE jobs SET state = $1, error = $2, steps = $3, finished_at = $4,"
                              " progress = CASE WHEN $5 THEN 1 ELSE progress END"
                              " WHERE id = $6 AND state IN ('queued', 'running')"};
constexpr PgStatement kStoreResult{"jobs_store_result",
                                   "INSERT INTO job_results(job_id, data) VALUES($1, $2)"
                                   " ON CONFLICT (job_id) DO UPDATE SET data = EXCLUDED.data"};
constexpr PgStatement kMarkRunningInterrupted{"jobs_mark_running_interrupted",
                                              "UPDATE jobs SET state = 'interrupted', finished_at = $1,"
                                              " error = 'the server stopped while the job was running'"
                                              " WHERE state = 'running'"};
// Results go with their job (ON DELETE CASCADE), in the same statement.
constexpr PgStatement kRemove{"jobs_remove", "DELETE FROM jobs WHERE id = $1"};
constexpr PgStatement kRemoveFinishedBefore{"jobs_remove_finished_before",
                                            "DELETE FROM jobs WHERE state IN ('done', 'failed', 'cancelled',"
                                            " 'interrupted', 'dead') AND finished_at < $1 AND NOT pinned"};

JobInfo readInfo(const pqxx::row& row)
{
    JobInfo j;
    j.id = row[0].as<std::int64_t>();
    j.ownerId = row[1].as<std::int64_t>();
    j.modelId = nullable<std::int64_t>(row[2]);
    jobStateFromName(row[3].as<std::string>(), j.state);
    j.progress = row[4].as<double>();
    j.error = row[5].as<std::string>();
    j.createdAt = row[6].as<std::int64_t>();
    j.startedAt = row[7].as<std::int64_t>();
    j.finishedAt = row[8].as<std::int64_t>();
    j.steps = static_cast<std::uint64_t>(row[9].as<std::int64_t>());
    j.start = row[10].as<double>();
    j.step = row[11].as<double>();
    j.stop = row[12].as<double>();
    j.logSamples = static_cast<std::size_t>(row[13].as<std::int64_t>());
    j.name = row[14].as<std::string>();
    j.pinned = row[15].as<bool>();
    j.resultsDropped = row[16].as<std::int64_t>() != 0;
    return j;
}

std::vector<JobInfo> readInfos(const pqxx::result& r)
{
    std::vector<JobInfo> jobs;
    jobs.reserve(r.size());
    for (const auto& row : r) jobs.push_back(readInfo(row));
    return jobs;
}

} // namespace

namespace {

std::int64_t insertQueuedJob(PostgresConnection& c, pqxx::transaction_base& tx, const JobRequest& request,
                             const JobInfo& resolved)
{
    const std::optional<std::string> modelId =
        request.modelId ? std::optional(std::to_string(*request.modelId)) : std::nullopt;
    return c.exec(tx, kCreate, request.ownerId, orNull(modelId), jobStateName(JobState::Queued),
                  static_cast<std::int64_t>(unixNow()), static_cast<std::int64_t>(resolved.steps), resolved.start,
                  resolved.step, resolved.stop, static_cast<std::int64_t>(resolved.logSamples),
                  request.toJson().dump())[0][0]
        .as<std::int64_t>();
}

} // namespace

std::int64_t PostgresJobStore::create(const JobRequest& request, const JobInfo& resolved)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return insertQueuedJob(c, tx, request, resolved);
    });
}

JobStore::Admission PostgresJobStore::createWithinQueueLimit(const JobRequest& request, const JobInfo& resolved,
                                                             int maxQueued)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        c.exec(tx, kAdmissionLock, kAdmissionLockClass, request.ownerId);
        Admission admission;
        admission.queued = c.exec(tx, kQueuedCount, request.ownerId)[0][0].as<int>();
        if (admission.queued >= maxQueued) return admission;
        admission.id = insertQueuedJob(c, tx, request, resolved);
        tx.commit();
        return admission;
    });
}

std::int64_t PostgresJobStore::createFinished(const JobRequest& request, const JobInfo& resolved,
                                             std::uint64_t steps, const std::string& resultBlob,
                                             const std::string& name)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        // create, markRunning, finish and label in one transaction: no claim sees it queued.
        pqxx::work tx(c.raw());
        const std::int64_t id = insertQueuedJob(c, tx, request, resolved);
        const auto now = static_cast<std::int64_t>(unixNow());
        if (c.exec(tx, kMarkRunning, now, id).affected_rows() != 1 ||
            c.exec(tx, kFinish, jobStateName(JobState::Done), std::string(), static_cast<std::int64_t>(steps), now,
                   true, id)
                    .affected_rows() != 1)
            throw StoreError(StoreErrc::Internal, "the finished job could not be stored");
        // Sent as binary (bytea) data, as finish sends it.
        c.exec(tx, kStoreResult, id, pqxx::binarystring(resultBlob.data(), resultBlob.size()));
        if (c.exec(tx, kLabel, name, orNull(std::optional<std::string>()), id).affected_rows() != 1)
            throw StoreError(StoreErrc::Internal, "the finished job could not be stored");
        tx.commit();
        return id;
    });
}

std::optional<JobInfo> PostgresJobStore::info(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<JobInfo> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kInfo, id);
        if (r.empty()) return std::nullopt;
        return readInfo(r[0]);
    });
}

std::optional<std::string> PostgresJobStore::requestText(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kRequest, id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

std::vector<JobInfo> PostgresJobStore::listForOwner(std::int64_t ownerId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return readInfos(c.exec(tx, kListForOwner, ownerId));
    });
}

std::vector<JobInfo> PostgresJobStore::listForModel(std::int64_t modelId, std::optional<std::int64_t> ownerId,
                                                   std::optional<std::int64_t> beforeId, int limit)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<JobInfo> jobs;
        const auto idText = [](std::optional<std::int64_t> id) {
            return id ? std::optional(std::to_string(*id)) : std::nullopt;
        };
        const std::optional<std::string> owner = idText(ownerId), before = idText(beforeId);
        for (const auto& row : c.exec(tx, kListForModel, modelId, orNull(owner), orNull(before), limit)) {
            JobInfo job = readInfo(row);
            job.parameters = parameterOverrides(row[17].is_null() ? "" : row[17].as<std::string>());
            if (!row[18].is_null()) job.usedParameters = parameterOverrides(row[18].as<std::string>());
            jobs.push_back(std::move(job));
        }
        return jobs;
    });
}

bool PostgresJobStore::label(std::int64_t id, const std::optional<std::string>& name, std::optional<bool> pinned)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        const std::optional<std::string> pinnedText =
            pinned ? std::optional<std::string>(*pinned ? "true" : "false") : std::nullopt;
        return c.exec(tx, kLabel, orNull(name), orNull(pinnedText), id).affected_rows() == 1;
    });
}

int PostgresJobStore::dropOldResults(std::int64_t modelId, int keep)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kDropOldResults, modelId, keep, static_cast<std::int64_t>(unixNow()))[0][0].as<int>();
    });
}

bool PostgresJobStore::dropResults(std::int64_t id)
{
    // Not idempotent: run twice, the second would say "gone already" of what the first dropped.
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kDropResults, id, static_cast<std::int64_t>(unixNow()))[0][0].as<int>() == 1;
    });
}

std::vector<JobInfo> PostgresJobStore::listAll()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return readInfos(c.exec(tx, kListAll));
    });
}

std::vector<JobInfo> PostgresJobStore::listInState(JobState state)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return readInfos(c.exec(tx, kListInState, jobStateName(state)));
    });
}

bool PostgresJobStore::markRunning(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kMarkRunning, static_cast<std::int64_t>(unixNow()), id).affected_rows() == 1;
    });
}

void PostgresJobStore::setProgress(std::int64_t id, double progress)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kSetProgress, progress, id);
    });
}

bool PostgresJobStore::finish(std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
                              const std::string* resultBlob)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        const auto updated = c.exec(tx, kFinish, jobStateName(state), error, static_cast<std::int64_t>(steps),
                                    static_cast<std::int64_t>(unixNow()), state == JobState::Done, id);
        if (updated.affected_rows() != 1) return false;   // finished already, or gone
        // Sent as binary (bytea) data: every byte value arrives as it is, no escaping involved.
        if (resultBlob) c.exec(tx, kStoreResult, id, pqxx::binarystring(resultBlob->data(), resultBlob->size()));
        tx.commit();
        return true;
    });
}

bool PostgresJobStore::remove(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemove, id).affected_rows() > 0;
    });
}

int PostgresJobStore::removeFinishedBefore(std::int64_t unixSeconds)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return static_cast<int>(c.exec(tx, kRemoveFinishedBefore, unixSeconds).affected_rows());
    });
}

} // namespace tlmhub::server
