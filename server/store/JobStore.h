#pragma once
// Jobs as stored (table jobs): state, timing, resolved settings and the request JSON, so a job
// can be run again. A finished job's result goes to table job_results in the same transaction
// (read through ResultStore).
#include "server/jobs/Job.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

class JobStore {
public:
    virtual ~JobStore() = default;

    // A new queued job; `resolved` gives the settings and planned steps (its other fields are
    // ignored). Returns the job id.
    virtual std::int64_t create(const JobRequest& request, const JobInfo& resolved) = 0;
    // The same, unless the owner already has `maxQueued` or more jobs queued (on every node).
    // The count and the insert are one transaction, so submits that race on any nodes cannot
    // pass the limit together.
    struct Admission {
        std::optional<std::int64_t> id; // nullopt: refused
        int queued = 0;                 // the owner's queued jobs before this one
    };
    virtual Admission createWithinQueueLimit(const JobRequest& request, const JobInfo& resolved, int maxQueued) = 0;

    // A job that ran and finished, stored in one transaction: the row `create` would insert,
    // then what markRunning, finish(Done, "", steps, &resultBlob) and label(name) would set
    // (state done, started and finished now, progress 1, the result, the name). It is never
    // queued where another transaction can see it, so no node's claim can take it. Returns
    // the job id; throws (nothing stored) when it cannot be stored.
    virtual std::int64_t createFinished(const JobRequest& request, const JobInfo& resolved, std::uint64_t steps,
                                        const std::string& resultBlob, const std::string& name) = 0;

    virtual std::optional<JobInfo> info(std::int64_t id) = 0;
    // The stored request's JSON text (JobRequest::toJson).
    virtual std::optional<std::string> requestText(std::int64_t id) = 0;
    // Newest first.
    virtual std::vector<JobInfo> listForOwner(std::int64_t ownerId) = 0;
    // A model's jobs, newest first, each with its parameter overrides: only `ownerId`'s when
    // given; at most `limit`, all with ids below `beforeId` when given (the next page).
    virtual std::vector<JobInfo> listForModel(std::int64_t modelId, std::optional<std::int64_t> ownerId,
                                              std::optional<std::int64_t> beforeId, int limit) = 0;
    // Sets the job's name and whether it is pinned, where given; false when there is no such job.
    virtual bool label(std::int64_t id, const std::optional<std::string>& name, std::optional<bool> pinned) = 0;
    // Of `modelId`'s finished, unpinned jobs that still have their results, all but the newest
    // `keep` lose them (the jobs stay, marked results-dropped); returns how many lost them.
    virtual int dropOldResults(std::int64_t modelId, int keep) = 0;
    // Drops one finished job's results (marks it results-dropped): true when this call
    // dropped them, false when they were gone already or there is no such finished job.
    virtual bool dropResults(std::int64_t id) = 0;
    virtual std::vector<JobInfo> listAll() = 0;
    // Oldest first (the order they were submitted in).
    virtual std::vector<JobInfo> listInState(JobState state) = 0;

    // queued -> running (sets started_at); false if the job is not queued any more.
    virtual bool markRunning(std::int64_t id) = 0;
    // Only while the job runs.
    virtual void setProgress(std::int64_t id, double progress) = 0;
    // Final state in one transaction: state, error, taken steps, finished_at and, when given,
    // the result (encodeResult's blob). Refuses (false) a job that is already finished or
    // gone; a failure writing the result leaves the job as it was.
    virtual bool finish(std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
                        const std::string* resultBlob) = 0;

    // Deletes the job and its result; works on a full disk too.
    virtual bool remove(std::int64_t id) = 0;
    // Deletes unpinned finished jobs (and their results) that finished before `unixSeconds`;
    // returns how many.
    virtual int removeFinishedBefore(std::int64_t unixSeconds) = 0;

    // The stored request; nullopt when the job does not exist or its text is not a request.
    std::optional<JobRequest> request(std::int64_t id);

protected:
    // The overrides of a stored request, from the JSON text of its "parameters" (empty when
    // the text is not such an object); the same for its "used_parameters".
    static std::map<std::string, std::string> parameterOverrides(const std::string& json);
};

} // namespace tlmhub::server
