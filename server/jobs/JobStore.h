#pragma once
// Persistence of jobs: table `jobs` (state, timing, resolved settings and the request JSON, so
// a job can be run again) and table `job_results` (blobs of server/store/ResultBlob).
#include "core/ResultTable.h"
#include "server/jobs/Job.h"
#include "server/store/Database.h"

#include <optional>
#include <vector>

namespace tlmhub::server {

class JobStore {
public:
    explicit JobStore(Database& db);

    // A new queued job; `resolved` gives the settings and planned steps (its other fields are
    // ignored). Returns the job id.
    std::int64_t create(const JobRequest& request, const JobInfo& resolved);

    std::optional<JobInfo> info(std::int64_t id);
    std::optional<JobRequest> request(std::int64_t id);
    // Newest first.
    std::vector<JobInfo> listForOwner(std::int64_t ownerId);
    std::vector<JobInfo> listAll();
    // Oldest first (the order they were submitted in).
    std::vector<JobInfo> listInState(JobState state);

    // queued -> running (sets started_at); false if the job is not queued any more.
    bool markRunning(std::int64_t id);
    void setProgress(std::int64_t id, double progress);
    // Final state in one transaction: state, error, taken steps, finished_at and, when given,
    // the result (encodeResult's blob). Refuses (false) a job that is already finished.
    bool finish(std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
                const std::string* resultBlob);
    // Start-up after a crash: every job left running becomes interrupted. Returns how many.
    int markRunningInterrupted();

    // The stored result with the columns `variables` names (empty: all); only those are
    // decompressed.
    std::optional<ResultTable> result(std::int64_t id, const std::vector<std::string>& variables = {});
    bool hasResult(std::int64_t id);
    bool remove(std::int64_t id);
    // Deletes finished jobs (and their results) that finished before `unixSeconds`;
    // returns how many.
    int removeFinishedBefore(std::int64_t unixSeconds);
    // Bytes of stored results of all of an owner's jobs (the storage quota).
    std::size_t storedBytes(std::int64_t ownerId);

private:
    std::vector<JobInfo> list(const std::string& where, std::int64_t value, const char* order);

    Database& mDb;
};

} // namespace tlmhub::server
