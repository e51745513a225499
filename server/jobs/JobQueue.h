#pragma once
// The job queue: compiles and stores submitted jobs, and runs them on a pool of worker
// threads (one worker per job; only a job alone on the server may use more, see jobThreads).
//
// Fairness: each user has a FIFO of queued jobs, and the workers serve users round robin,
// skipping users who already run JobLimits::maxRunningPerUser jobs. A user with many queued
// jobs therefore delays another user's job by at most one job per worker.
#include "server/jobs/Job.h"
#include "server/jobs/JobRunner.h"
#include "server/jobs/JobStore.h"
#include "server/jobs/PreparedJob.h"
#include "server/jobs/StreamHub.h"

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace tlmhub::server {

// RunOptions::threads for a job that starts now: automatic (one per core while that is
// faster) only when no other job is queued or running; otherwise the workers already use the
// cores, and a job's second thread would wait at every phase barrier for a core.
unsigned jobThreads(bool otherJobsQueued, bool otherJobsRunning);

class JobQueue {
public:
    JobQueue(JobStore& store, StreamHub& hub, JobLimits limits, unsigned workers);
    ~JobQueue();   // shutdown()
    JobQueue(const JobQueue&) = delete;
    JobQueue& operator=(const JobQueue&) = delete;

    // Marks jobs left running by a crash as interrupted, queues the stored queued jobs (a
    // restart continues where the last run stopped) and starts the workers.
    void start();
    // Stops running jobs (they become interrupted), joins the workers. Queued jobs stay
    // queued in the store for the next start().
    void shutdown();

    struct Submitted {
        std::optional<std::int64_t> id;
        std::string code, message;   // limit_exceeded, invalid_model, invalid_parameter, bad_request
    };
    // Compiles the job (loads the model, applies parameters, checks limits) before queuing;
    // the worker runs that compiled job.
    Submitted submit(const JobRequest& request);
    // The same for a model in memory whose text request.hmf holds (see prepareJob).
    Submitted submit(const JobRequest& request, Model model);
    // Queued jobs held compiled in memory (the others are compiled again when they run).
    std::size_t compiledQueued();
    // Beyond this many, a queued job keeps only its stored request: memory stays bounded.
    static constexpr std::size_t kMaxCompiledQueued = 256;

    // Never waits: a queued job is cancelled at once; a running one is asked to stop, and its
    // event.done (cancelled) follows when it has. NotActive: neither queued nor running.
    enum class CancelRequest { NotActive, Cancelled, Cancelling };
    CancelRequest requestCancel(std::int64_t jobId);
    // The same, and for a running job the call waits (a few seconds at most) until the job
    // has reached its final state. False if the job is not queued or running.
    bool cancel(std::int64_t jobId);

    // Subscribe to a job's events (see StreamHub). A job that has already finished gets one
    // frame with its whole result and event.done at once, on the calling thread.
    std::uint64_t subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate,
                            StreamSink sink);

    JobStore& store() { return mStore; }
    StreamHub& hub() { return mHub; }
    const JobLimits& limits() const { return mLimits; }

private:
    void workerLoop();
    // Next job by the fairness rule; counts it as running. Caller holds mMutex.
    bool pickNext(std::int64_t& jobId, std::int64_t& ownerId);
    void enqueue(std::int64_t ownerId, std::int64_t jobId);   // caller holds mMutex
    bool removeQueued(std::int64_t jobId);                      // caller holds mMutex
    bool isQueuedInMemory(std::int64_t jobId) const;            // caller holds mMutex
    Submitted queue(const JobRequest& request, std::unique_ptr<PreparedJob> prepared);

    JobStore& mStore;
    StreamHub& mHub;
    JobLimits mLimits;
    JobRunner mRunner;
    unsigned mWorkerCount;

    std::mutex mMutex;
    std::condition_variable mWake;       // a job was queued, a worker freed, or stopping
    std::condition_variable mJobEnded;   // a running job reached its final state
    std::map<std::int64_t, std::deque<std::int64_t>> mQueued;   // owner -> job ids, FIFO
    std::deque<std::int64_t> mRotation;                        // owners with queued jobs, next first
    std::map<std::int64_t, int> mRunningPerOwner;
    std::map<std::int64_t, std::shared_ptr<JobControl>> mActive;   // running job -> control
    std::map<std::int64_t, std::unique_ptr<PreparedJob>> mCompiled;   // queued job -> compiled
    std::vector<std::thread> mWorkers;
    bool mStarted = false;
    bool mStopping = false;
};

} // namespace tlmhub::server
