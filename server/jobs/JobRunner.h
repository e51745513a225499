#pragma once
// Runs one compiled job on the calling thread to its final state: initialise, simulate with
// progress/frames/wall-time checks, store the result and the state, publish event.done.
#include "server/jobs/Job.h"
#include "server/jobs/JobStore.h"
#include "server/jobs/PreparedJob.h"
#include "server/jobs/StreamHub.h"

#include <atomic>
#include <chrono>
#include <mutex>

namespace tlmhub {
class System;
}

namespace tlmhub::server {

// Stops a running job from another thread (cancel, shutdown). The runner attaches the job's
// System while it exists, so a stop request reaches the simulation loop at once; a request
// that arrives before (or during) initialize is seen when the run starts.
class JobControl {
public:
    enum class Stop { None, Cancel, Shutdown };

    void requestStop(Stop reason);
    Stop stopReason() const { return mReason.load(); }

    void attach(System* system);
    void detach();

private:
    std::mutex mMutex;
    System* mSystem = nullptr;
    std::atomic<Stop> mReason{Stop::None};
};

class JobRunner {
public:
    JobRunner(JobStore& store, StreamHub& hub, const JobLimits& limits);

    // The job must already be marked running in the store. Returns its final state.
    // `threads` as RunOptions::threads (see jobThreads).
    JobState run(std::int64_t jobId, PreparedJob& job, JobControl& control, unsigned threads);
    // A job whose compiled form was not kept (queued before a restart): prepared from its request.
    JobState run(std::int64_t jobId, const JobRequest& request, JobControl& control, unsigned threads);

    // Steps between two progress callbacks: a clock read per 256 steps costs well under 1%
    // even for the smallest models, and bounds how late a wall-time limit is noticed.
    static constexpr std::size_t kProgressInterval = 256;
    static constexpr auto kProgressEventPeriod = std::chrono::milliseconds(100);
    static constexpr auto kProgressStorePeriod = std::chrono::seconds(1);
    static constexpr auto kFramePollPeriod = std::chrono::milliseconds(5);

private:
    struct RunState;
    static void onProgress(void* user, std::size_t stepsTaken, std::size_t stepsTotal);
    // A finished run's result: what is stored, and where its last frames come from.
    struct Result {
        const std::string& blob;
        LiveFrameSource samples;
    };
    JobState finish(std::int64_t jobId, JobState state, const std::string& error, std::uint64_t steps,
                    const Result* result);

    JobStore& mStore;
    StreamHub& mHub;
    JobLimits mLimits;
};

// "wall time limit (N s) exceeded"
std::string wallTimeLimitMessage(double seconds);

} // namespace tlmhub::server
