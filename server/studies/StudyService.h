#pragma once
// Studies as the API sees them: submission (checked and compiled up front, so a study that
// cannot run is refused with a clear error before anything is queued), cancellation, restart
// after a server stop, and the study's results as one table.
#include "server/jobs/JobQueue.h"
#include "server/jobs/QueueNode.h"
#include "server/store/ResultStore.h"
#include "server/store/StudyStore.h"
#include "server/studies/StudyExecution.h"
#include "server/studies/StudyProgressHub.h"

#include <nlohmann/json.hpp>

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

namespace tlmhub::server {

class StudyService {
public:
    // `node`: this node, which holds the studies it accepts (server/store/StudyStore.h).
    StudyService(StudyStore& store, ResultStore& results, JobQueue& queue, StudyProgressHub& hub,
                 const JobLimits& jobLimits, StudyLimits limits, unsigned workers, QueueNode node);
    ~StudyService();

    // Before the queue starts, on an API node (role api or all; a worker runs no studies):
    // studies whose node stopped answering are taken over, now and every lease time / 3
    // from then on: running ones become interrupted, queued ones run here from their
    // stored request. Studies other nodes hold are left alone.
    void start();
    // At shutdown: no more taking over, and this node's queued studies are released for the
    // next node that starts or looks (one that a worker takes meanwhile no longer starts
    // here: StudyStore::markRunning). The queue's shutdown then ends the started ones interrupted.
    void stop();

    struct Submitted {
        std::optional<std::int64_t> id;
        std::size_t runsTotal = 0;
        std::string code, message;   // bad_request, limit_exceeded, invalid_model, invalid_parameter, ...
    };
    // `body` as POST /studies takes it; `hmf` the model's text (from model_id, or the body's).
    Submitted submit(std::int64_t ownerId, const nlohmann::json& body, const std::string& hmf);
    // Cancels a queued or running study; false when it is neither.
    bool cancel(std::int64_t id);
    // Queues an interrupted or cancelled study again, from the request and model text stored
    // at submission, to run only the runs it lacks (code "conflict" in any other state).
    Submitted resume(const StudyInfo& info);

    // {id, kind, name, model_id, state, runs_total, runs_done, runs_failed, progress, error,
    //  created_at, started_at, finished_at, summary} (the summary without its bands).
    static nlohmann::json infoJson(const StudyInfo& info);
    struct Table {
        std::vector<std::string> columns;
        std::vector<nlohmann::json> rows;   // arrays in column order; null for no value
        std::vector<std::string> nodes;     // per row: the node that ran it ("" before schema 9)
        std::map<std::int64_t, std::string> errors;   // failed runs: why
    };
    // The runs finished so far; nullopt when the study's request is unreadable.
    std::optional<Table> table(std::int64_t id);
    static std::string tableCsv(const Table& table);
    // A sensitivity study's bands as CSV (time, then per variable mean-2sd, mean-sd, mean,
    // mean+sd, mean+2sd) or JSON; nullopt when it has none (yet).
    std::optional<std::string> bandsCsv(const StudyInfo& info);
    std::optional<nlohmann::json> bandsJson(const StudyInfo& info);

    StudyStore& store() { return mStore; }
    StudyProgressHub& hub() { return mHub; }
    const StudyLimits& limits() const { return mLimits; }

private:
    // A stored queued study into the queue, with the runs it has already; a code on failure.
    Submitted enqueueStored(const StudyInfo& info);
    // Takes over the studies of nodes that stopped answering (StudyStore::adoptOrphans).
    void adoptOrphans();
    void watchOrphans(std::stop_token stop);
    // Refusal while the owner has as many studies queued or running as allowed.
    std::optional<Submitted> overActiveLimit(std::int64_t ownerId);
    // Parses, checks and compiles; fills `prepared` (id and owner aside), held by this node.
    Submitted prepare(std::int64_t ownerId, const nlohmann::json& body, const std::string& hmf,
                      PreparedStudy& prepared);

    StudyStore& mStore;
    ResultStore& mResults;
    JobQueue& mQueue;
    StudyProgressHub& mHub;
    JobLimits mJobLimits;
    StudyLimits mLimits;
    unsigned mWorkers;
    QueueNode mNode;
    std::mutex mWatchMutex;
    std::condition_variable_any mWatchWake;
    std::jthread mWatcher;
};

} // namespace tlmhub::server
