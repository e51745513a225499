#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"

namespace tlmhub::server {

namespace {

#define TLMHUB_STUDY_INFO                                                                       \
    "SELECT id, owner_id, model_id, kind, name, state, runs_total, runs_done, runs_failed,"    \
    " error, created_at, started_at, finished_at, summary FROM studies"
constexpr PgStatement kCreate{"studies_create",
                              "INSERT INTO studies(owner_id, model_id, kind, name, state, runs_total, created_at,"
                              " request) VALUES($1, $2, $3, $4, $5, $6, $7, $8) RETURNING id"};
constexpr PgStatement kInfo{"studies_info", TLMHUB_STUDY_INFO " WHERE id = $1"};
constexpr PgStatement kListForOwner{"studies_list_for_owner", TLMHUB_STUDY_INFO " WHERE owner_id = $1 ORDER BY id DESC"};
constexpr PgStatement kListInState{"studies_list_in_state", TLMHUB_STUDY_INFO " WHERE state = $1 ORDER BY id ASC"};
#undef TLMHUB_STUDY_INFO
constexpr PgStatement kRequest{"studies_request", "SELECT request FROM studies WHERE id = $1"};
constexpr PgStatement kMarkRunning{"studies_mark_running",
                                   "UPDATE studies SET state = 'running', started_at = $1"
                                   " WHERE id = $2 AND state = 'queued'"};
constexpr PgStatement kCountRun{"studies_count_run",
                                "UPDATE studies SET runs_done = runs_done + $1, runs_failed = runs_failed + $2"
                                " WHERE id = $3 AND state = 'running'"};
// A run index taken already inserts nothing, and the transaction is rolled back.
constexpr PgStatement kInsertRun{"studies_insert_run",
                                 "INSERT INTO study_runs(study_id, run_index, ok, parameters, outputs, error, result)"
                                 " VALUES($1, $2, $3, $4, $5, $6, $7) ON CONFLICT DO NOTHING"};
constexpr PgStatement kSetSummary{"studies_set_summary",
                                  "UPDATE studies SET summary = $1 WHERE id = $2 AND state IN ('queued', 'running')"};
constexpr PgStatement kFinish{"studies_finish",
                              "UPDATE studies SET state = $1, error = $2, summary = $3, finished_at = $4"
                              " WHERE id = $5 AND state IN ('queued', 'running')"};
constexpr PgStatement kMarkRunningInterrupted{"studies_mark_running_interrupted",
                                              "UPDATE studies SET state = 'interrupted', finished_at = $1,"
                                              " error = 'the server stopped while the study was running'"
                                              " WHERE state = 'running'"};
constexpr PgStatement kReopen{"studies_reopen",
                              "UPDATE studies SET state = 'queued', error = '', finished_at = 0"
                              " WHERE id = $1 AND state IN ('interrupted', 'cancelled')"};
constexpr PgStatement kRuns{"studies_runs",
                            "SELECT run_index, ok, parameters, outputs, error, result IS NOT NULL FROM study_runs"
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
                                                        const std::string& request, std::int64_t runsTotal)
{
    const std::optional<std::string> model = modelId ? std::optional(std::to_string(*modelId)) : std::nullopt;
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kCreate, ownerId, orNull(model), kind, name, jobStateName(JobState::Queued), runsTotal,
                          static_cast<std::int64_t>(unixNow()), request)[0][0]
                .as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such owner
        }
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

bool PostgresStudyStore::markRunning(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kMarkRunning, static_cast<std::int64_t>(unixNow()), id).affected_rows() == 1;
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
                                pqxx::binarystring(resultBlob->data(), resultBlob->size()))
                       : c.exec(tx, kInsertRun, studyId, run.index, run.ok, run.parameters, run.outputs, run.error,
                                static_cast<const char*>(nullptr));
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

int PostgresStudyStore::markRunningInterrupted()
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return static_cast<int>(
            c.exec(tx, kMarkRunningInterrupted, static_cast<std::int64_t>(unixNow())).affected_rows());
    });
}

bool PostgresStudyStore::reopen(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kReopen, id).affected_rows() == 1;
    });
}

std::vector<StudyRun> PostgresStudyStore::runs(std::int64_t studyId, std::int64_t fromIndex, std::size_t limit)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<StudyRun> out;
        for (const auto& row : c.exec(tx, kRuns, studyId, fromIndex, static_cast<std::int64_t>(limit)))
            out.push_back(StudyRun{row[0].as<std::int64_t>(), row[1].as<bool>(), row[2].as<std::string>(),
                                   row[3].as<std::string>(), row[4].as<std::string>(), row[5].as<bool>()});
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
