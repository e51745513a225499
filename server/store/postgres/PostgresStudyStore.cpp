#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

#define TLMHUB_STUDY_INFO                                                                       \
    "SELECT id, owner_id, model_id, kind, name, state, runs_total, runs_done, runs_failed,"    \
    " error, created_at, started_at, finished_at, summary FROM studies"
constexpr PgStatement kCreate{"studies_create",
                              "INSERT INTO studies(owner_id, model_id, kind, name, state, runs_total, created_at,"
                              " request, node) VALUES($1, $2, $3, $4, $5, $6, $7, $8, $9) RETURNING id"};
// The owner's row, locked until the transaction ends: the admissions of one user's studies
// (count, then insert or reopen) take turns across all nodes.
constexpr PgStatement kLockOwner{"studies_lock_owner", "SELECT 1 FROM users WHERE id = $1 FOR UPDATE"};
constexpr PgStatement kActiveCount{"studies_active_count",
                                   "SELECT COUNT(*) FROM studies WHERE owner_id = $1 AND state IN ('queued', 'running')"};
constexpr PgStatement kOwnerOf{"studies_owner_of", "SELECT owner_id FROM studies WHERE id = $1"};
constexpr PgStatement kInfo{"studies_info", TLMHUB_STUDY_INFO " WHERE id = $1"};
constexpr PgStatement kListForOwner{"studies_list_for_owner", TLMHUB_STUDY_INFO " WHERE owner_id = $1 ORDER BY id DESC"};
constexpr PgStatement kListInState{"studies_list_in_state", TLMHUB_STUDY_INFO " WHERE state = $1 ORDER BY id ASC"};
#undef TLMHUB_STUDY_INFO
constexpr PgStatement kRequest{"studies_request", "SELECT request FROM studies WHERE id = $1"};
constexpr PgStatement kMarkRunning{"studies_mark_running",
                                   "UPDATE studies SET state = 'running', started_at = $1"
                                   " WHERE id = $2 AND state = 'queued' AND node = $3"};
constexpr PgStatement kCountRun{"studies_count_run",
                                "UPDATE studies SET runs_done = runs_done + $1, runs_failed = runs_failed + $2"
                                " WHERE id = $3 AND state = 'running'"};
// A run index taken already inserts nothing, and the transaction is rolled back.
constexpr PgStatement kInsertRun{"studies_insert_run",
                                 "INSERT INTO study_runs(study_id, run_index, ok, parameters, outputs, error, result, node)"
                                 " VALUES($1, $2, $3, $4, $5, $6, $7, $8) ON CONFLICT DO NOTHING"};
constexpr PgStatement kSetSummary{"studies_set_summary",
                                  "UPDATE studies SET summary = $1 WHERE id = $2 AND state IN ('queued', 'running')"};
constexpr PgStatement kFinish{"studies_finish",
                              "UPDATE studies SET state = $1, error = $2, summary = $3, finished_at = $4"
                              " WHERE id = $5 AND state IN ('queued', 'running')"};
// Studies held by no node that answers: none, or one not seen for $1 ms, other than $2.
#define TLMHUB_ORPHANED                                                                                   \
    " (node IS NULL OR (node <> $2 AND node NOT IN"                                                       \
    " (SELECT id FROM nodes WHERE last_seen >= " TLMHUB_NOW_MS " - $1)))"
constexpr PgStatement kInterruptOrphans{"studies_interrupt_orphans",
                                        "UPDATE studies SET state = 'interrupted', finished_at = $3,"
                                        " error = 'its server stopped while the study was running'"
                                        " WHERE state = 'running' AND" TLMHUB_ORPHANED};
constexpr PgStatement kAdoptOrphans{"studies_adopt_orphans",
                                    "UPDATE studies SET node = $2 WHERE state = 'queued' AND" TLMHUB_ORPHANED " RETURNING id"};
#undef TLMHUB_ORPHANED
constexpr PgStatement kReleaseQueued{"studies_release_queued",
                                     "UPDATE studies SET node = NULL WHERE node = $1 AND state = 'queued'"};
constexpr PgStatement kReopen{"studies_reopen",
                              "UPDATE studies SET state = 'queued', error = '', finished_at = 0, node = $2"
                              " WHERE id = $1 AND state IN ('interrupted', 'cancelled')"};
constexpr PgStatement kRuns{"studies_runs",
                            "SELECT run_index, ok, parameters, outputs, error, result IS NOT NULL, node FROM study_runs"
                            " WHERE study_id = $1 AND run_index >= $2 ORDER BY run_index LIMIT $3"};
constexpr PgStatement kRunResult{"studies_run_result",
                                 "SELECT result FROM study_runs WHERE study_id = $1 AND run_index = $2"
                                 " AND result IS NOT NULL"};
constexpr PgStatement kStoredBytes{"studies_stored_bytes",
                                   "SELECT COALESCE(SUM(octet_length(r.result)), 0)::BIGINT FROM study_runs r"
                                   " JOIN studies s ON s.id = r.study_id WHERE s.owner_id = $1"};
// The runs go with their study (ON DELETE CASCADE), in the same statement.
constexpr PgStatement kRemove{"studies_remove", "DELETE FROM studies WHERE id = $1"};

StudyInfo readInfo(const pqxx::row& row)
{
    StudyInfo s;
    s.id = row[0].as<std::int64_t>();
    s.ownerId = row[1].as<std::int64_t>();
    s.modelId = nullable<std::int64_t>(row[2]);
    s.kind = row[3].as<std::string>();
    s.name = row[4].as<std::string>();
    jobStateFromName(row[5].as<std::string>(), s.state);
    s.runsTotal = row[6].as<std::int64_t>();
    s.runsDone = row[7].as<std::int64_t>();
    s.runsFailed = row[8].as<std::int64_t>();
    s.error = row[9].as<std::string>();
    s.createdAt = row[10].as<std::int64_t>();
    s.startedAt = row[11].as<std::int64_t>();
    s.finishedAt = row[12].as<std::int64_t>();
    s.summary = row[13].as<std::string>();
    return s;
}

std::vector<StudyInfo> readInfos(const pqxx::result& r)
{
    std::vector<StudyInfo> studies;
    studies.reserve(r.size());
    for (const auto& row : r) studies.push_back(readInfo(row));
    return studies;
}

} // namespace

std::optional<std::int64_t> PostgresStudyStore::create(std::int64_t ownerId, std::optional<std::int64_t> modelId,
                                                        const std::string& kind, const std::string& name,
                                                        const std::string& request, std::int64_t runsTotal,
                                                        const std::string& node, int maxActive)
{
    const std::optional<std::string> model = modelId ? std::optional(std::to_string(*modelId)) : std::nullopt;
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::work tx(c.raw());
        if (c.exec(tx, kLockOwner, ownerId).empty()) return std::nullopt;   // no such owner
        if (c.exec(tx, kActiveCount, ownerId)[0][0].as<int>() >= maxActive) return std::nullopt;
        const auto id = c.exec(tx, kCreate, ownerId, orNull(model), kind, name, jobStateName(JobState::Queued), runsTotal,
                               static_cast<std::int64_t>(unixNow()), request, node)[0][0]
                            .as<std::int64_t>();
        tx.commit();
        return id;
    });
}

std::optional<StudyInfo> PostgresStudyStore::info(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<StudyInfo> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kInfo, id);
        if (r.empty()) return std::nullopt;
        return readInfo(r[0]);
    });
}

std::optional<std::string> PostgresStudyStore::request(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kRequest, id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

std::vector<StudyInfo> PostgresStudyStore::listForOwner(std::int64_t ownerId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return readInfos(c.exec(tx, kListForOwner, ownerId));
    });
}

std::vector<StudyInfo> PostgresStudyStore::listInState(JobState state)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return readInfos(c.exec(tx, kListInState, jobStateName(state)));
    });
}

int PostgresStudyStore::activeCount(std::int64_t ownerId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kActiveCount, ownerId)[0][0].as<int>();
    });
}

bool PostgresStudyStore::markRunning(std::int64_t id, const std::string& node)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kMarkRunning, static_cast<std::int64_t>(unixNow()), id, node).affected_rows() == 1;
    });
}

bool PostgresStudyStore::addRun(std::int64_t studyId, const StudyRun& run, const std::string* resultBlob)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        // The update locks the study's row: a finish waits until this run is counted.
        if (c.exec(tx, kCountRun, run.ok ? 1 : 0, run.ok ? 0 : 1, studyId).affected_rows() != 1) return false;
        // Sent as binary (bytea) data; a null pointer is NULL (no result kept).
        const auto inserted =
            resultBlob ? c.exec(tx, kInsertRun, studyId, run.index, run.ok, run.parameters, run.outputs, run.error,
                                pqxx::binarystring(resultBlob->data(), resultBlob->size()), run.node)
                       : c.exec(tx, kInsertRun, studyId, run.index, run.ok, run.parameters, run.outputs, run.error,
                                static_cast<const char*>(nullptr), run.node);
        if (inserted.affected_rows() != 1) return false;
        tx.commit();
        return true;
    });
}

void PostgresStudyStore::setSummary(std::int64_t id, const std::string& summary)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kSetSummary, summary, id);
    });
}

bool PostgresStudyStore::finish(std::int64_t id, JobState state, const std::string& error, const std::string& summary)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kFinish, jobStateName(state), error, summary, static_cast<std::int64_t>(unixNow()), id)
                   .affected_rows() == 1;
    });
}

std::vector<StudyInfo> PostgresStudyStore::adoptOrphans(const std::string& node, std::chrono::milliseconds within)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        const auto since = static_cast<std::int64_t>(within.count());
        c.exec(tx, kInterruptOrphans, since, node, static_cast<std::int64_t>(unixNow()));
        std::vector<std::int64_t> ids;
        for (const auto& row : c.exec(tx, kAdoptOrphans, since, node)) ids.push_back(row[0].as<std::int64_t>());
        std::sort(ids.begin(), ids.end());
        std::vector<StudyInfo> adopted;
        for (const std::int64_t id : ids) {
            const auto r = c.exec(tx, kInfo, id);
            if (!r.empty()) adopted.push_back(readInfo(r[0]));
        }
        tx.commit();
        return adopted;
    });
}

void PostgresStudyStore::releaseQueued(const std::string& node)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kReleaseQueued, node);
    });
}

bool PostgresStudyStore::reopen(std::int64_t id, const std::string& node, int maxActive)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        const auto owner = c.exec(tx, kOwnerOf, id);
        if (owner.empty()) return false;
        const auto ownerId = owner[0][0].as<std::int64_t>();
        if (c.exec(tx, kLockOwner, ownerId).empty()) return false;
        if (c.exec(tx, kActiveCount, ownerId)[0][0].as<int>() >= maxActive) return false;
        if (c.exec(tx, kReopen, id, node).affected_rows() != 1) return false;
        tx.commit();
        return true;
    });
}

std::vector<StudyRun> PostgresStudyStore::runs(std::int64_t studyId, std::int64_t fromIndex, std::size_t limit)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<StudyRun> out;
        for (const auto& row : c.exec(tx, kRuns, studyId, fromIndex, static_cast<std::int64_t>(limit)))
            out.push_back(StudyRun{row[0].as<std::int64_t>(), row[1].as<bool>(), row[2].as<std::string>(),
                                   row[3].as<std::string>(), row[4].as<std::string>(), row[5].as<bool>(),
                                   row[6].as<std::string>()});
        return out;
    });
}

std::optional<std::string> PostgresStudyStore::runResult(std::int64_t studyId, std::int64_t index)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kRunResult, studyId, index);
        if (r.empty()) return std::nullopt;
        // The text form of bytea, decoded back to the stored bytes.
        const pqxx::binarystring data(r[0][0]);
        return data.str();
    });
}

std::size_t PostgresStudyStore::storedBytes(std::int64_t ownerId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kStoredBytes, ownerId)[0][0].as<std::size_t>();
    });
}

bool PostgresStudyStore::remove(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemove, id).affected_rows() > 0;
    });
}

} // namespace tlmhub::server
