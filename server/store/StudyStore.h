#pragma once
// Studies as stored (tables studies and study_runs): a study is many runs of one model with
// other parameters (a sweep, a Monte Carlo sensitivity analysis, an optimisation). The study
// row keeps its request, state and counters; each finished run adds a row with its
// parameters, its scalar outputs and, when the study keeps full variables, its result
// (encodeResult's blob, as a job's). Run blobs count against their owner's stored bytes.
//
// A queued or running study is held by a node (docs/scale-out.md): the node that queues and
// runs it. Only that node starts it; another takes it over only once the holder has stopped
// answering (no heartbeat in the nodes table within a lease time).
#include "server/jobs/Job.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct StudyInfo {
    std::int64_t id = 0, ownerId = 0;
    std::optional<std::int64_t> modelId;
    std::string kind;                       // sweep, sensitivity, optimise
    std::string name;
    JobState state = JobState::Queued;      // the job states, with the same transitions
    std::int64_t runsTotal = 0;             // planned (optimise: the evaluation budget)
    std::int64_t runsDone = 0, runsFailed = 0;
    std::string error;
    std::int64_t createdAt = 0, startedAt = 0, finishedAt = 0;   // unix s; 0 = not yet
    std::string summary;                    // JSON text: best point, bands...; "" until set
};

struct StudyRun {
    std::int64_t index = 0;                 // 0-based, unique within its study
    bool ok = true;                         // false: the run failed (error says why)
    std::string parameters;                 // JSON object text: name -> value
    std::string outputs;                    // JSON object text: column -> value
    std::string error;
    bool hasResult = false;                 // a full result blob is stored
    std::string node;                       // the node that ran it
};

class StudyStore {
public:
    virtual ~StudyStore() = default;

    // A new queued study held by `node`; `request` is the request JSON text (kept to run it
    // again after a restart). Returns the study id, or nullopt when the owner does not exist
    // or already has `maxActive` studies queued or running on any node (counted and inserted
    // in one transaction, so two nodes cannot both admit the last one).
    virtual std::optional<std::int64_t> create(std::int64_t ownerId, std::optional<std::int64_t> modelId,
                                               const std::string& kind, const std::string& name,
                                               const std::string& request, std::int64_t runsTotal,
                                               const std::string& node, int maxActive) = 0;
    virtual std::optional<StudyInfo> info(std::int64_t id) = 0;
    virtual std::optional<std::string> request(std::int64_t id) = 0;
    // Newest first.
    virtual std::vector<StudyInfo> listForOwner(std::int64_t ownerId) = 0;
    // Oldest first.
    virtual std::vector<StudyInfo> listInState(JobState state) = 0;
    // The owner's studies queued or running, on every node.
    virtual int activeCount(std::int64_t ownerId) = 0;

    // queued -> running (sets started_at); false if it is not queued any more or another
    // node holds it now (it was taken over while this one stalled).
    virtual bool markRunning(std::int64_t id, const std::string& node) = 0;
    // Adds a finished run (and its result blob when `resultBlob` is given) and counts it in
    // runs_done or runs_failed, in one transaction. False when the study is not running or the
    // run index exists already.
    virtual bool addRun(std::int64_t studyId, const StudyRun& run, const std::string* resultBlob) = 0;
    // Replaces the summary JSON while the study runs (best so far).
    virtual void setSummary(std::int64_t id, const std::string& summary) = 0;
    // Final state, error, summary and finished_at; false when already finished or gone.
    virtual bool finish(std::int64_t id, JobState state, const std::string& error, const std::string& summary) = 0;
    // Studies whose holder is gone (no node of that id seen within `within`, or none at all),
    // other than `node`'s: the running ones become interrupted (their runs so far are kept;
    // they resume), and `node` takes over the queued ones, which it returns, oldest first.
    virtual std::vector<StudyInfo> adoptOrphans(const std::string& node, std::chrono::milliseconds within) = 0;
    // A node that stops: its queued studies are held by none, for the next node to adopt at once.
    virtual void releaseQueued(const std::string& node) = 0;
    // Resume: an interrupted or cancelled study is queued again, held by `node`, with its runs
    // and counters, to run the runs it lacks (error and finished_at cleared). False in any
    // other state, or when the owner already has `maxActive` studies queued or running.
    virtual bool reopen(std::int64_t id, const std::string& node, int maxActive) = 0;

    // Runs with index >= fromIndex in index order, at most `limit` (no blobs).
    virtual std::vector<StudyRun> runs(std::int64_t studyId, std::int64_t fromIndex, std::size_t limit) = 0;
    // The stored result of a run, nullopt when there is none.
    virtual std::optional<std::string> runResult(std::int64_t studyId, std::int64_t index) = 0;
    // Bytes of run results the owner's studies hold.
    virtual std::size_t storedBytes(std::int64_t ownerId) = 0;

    // Deletes the study with its runs; works on a full disk too.
    virtual bool remove(std::int64_t id) = 0;
};

} // namespace tlmhub::server
