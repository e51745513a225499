#pragma once
// Runs jobs in time slices on the calling (worker) thread. A job's first slice initialises
// it; each slice simulates until the job is done, or until it has run a while (kFirstSlice,
// kSlice) while other jobs wait (the queue then parks it and runs another one: see
// JobQueue.h); the last one stores the result and the state and publishes event.done, if
// this node still holds the job's lease (JobLeaseStore.h): else it stores nothing.
// Slices give the same result as one whole run (Simulation's RunOptions::pause).
#include "server/jobs/FrameSource.h"
#include "server/jobs/Job.h"
#include "server/store/JobLeaseStore.h"
#include "server/store/JobStore.h"
#include "server/jobs/PreparedJob.h"
#include "server/jobs/StreamHub.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>

namespace tlmhub {
class System;
}

namespace tlmhub::server {

// Stops a started job from another thread (cancel, shutdown). The runner attaches the job's
// System from its start to its end, also while it is parked between slices, so a stop
// request reaches the simulation loop at once, or the job's next slice; a request that
// arrives before (or during) initialize is seen when the run starts.
class JobControl {
public:
    // Shutdown: the job ends interrupted. Release: it goes back to the queue for another node
    // (a worker node that stops). LeaseLost: another node has taken it over; nothing is stored.
    enum class Stop { None, Cancel, Shutdown, Release, LeaseLost };

    void requestStop(Stop reason);
    Stop stopReason() const { return mReason.load(); }

    void attach(System* system);
    void detach();

private:
    std::mutex mMutex;
    System* mSystem = nullptr;
    std::atomic<Stop> mReason{Stop::None};
};

// A job from its start to its final state: its simulation and what its slices carry over.
// Only one thread at a time touches it (the worker running its slice).
class StartedJob {
public:
    // `compiled`: null for a job submitted on another node or before a restart, prepared again
    // from its stored request. `lease`: this node's claim of the job (it is running in the store).
    StartedJob(const JobLease& lease, std::unique_ptr<PreparedJob> compiled, std::shared_ptr<JobControl> control);
    ~StartedJob();

    std::int64_t id() const { return mId; }
    // Bytes of log storage it holds from its first slice on (a lower bound of its result).
    std::size_t logBytes() const { return mLogBytes; }

private:
    friend class JobRunner;
    using Clock = std::chrono::steady_clock;

    std::int64_t mId;
    JobLease mLease;
    std::unique_ptr<PreparedJob> mJob;
    std::shared_ptr<JobControl> mControl;
    bool mInitialised = false;
    std::optional<LiveFrameSource> mLive;   // once initialised
    std::size_t mLogBytes = 0;
    Clock::duration mRunTime{};             // of its slices so far: the wall time limit
    Clock::time_point mLastProgressEvent{}, mLastProgressStore{}, mLastFramePoll{};

    // The running slice's, for the progress callback.
    Clock::time_point mSliceStart{};
    Clock::duration mSliceLength{};
    const std::atomic<bool>* mOthersWaiting = nullptr;
    std::stop_source mPause;
    bool mWallTimeExceeded = false;
};

class JobRunner {
public:
    JobRunner(JobStore& store, JobLeaseStore& leases, StreamHub& hub, const JobLimits& limits);

    // Runs the job's next slice with `threads` as RunOptions::threads (see jobThreads). The
    // slice ends after kFirstSlice (the first) or kSlice at the first progress check that
    // finds `othersWaiting` set.
    // True when the job has reached its final state (stored, event.done published); false
    // when it is paused, its new samples published as frames.
    bool runSlice(StartedJob& job, unsigned threads, const std::atomic<bool>& othersWaiting);
    // A frame of what a parked job has logged for each subscription due one (one that came
    // since its last slice): on any thread, while no worker runs the job.
    void publishFrames(StartedJob& job);

    // Steps between two progress callbacks: a clock read per 256 steps costs well under 1%
    // even for the smallest models, and bounds how late a wall-time limit or the end of a
    // slice is noticed.
    static constexpr std::size_t kProgressInterval = 256;
    static constexpr auto kProgressEventPeriod = std::chrono::milliseconds(100);
    static constexpr auto kProgressStorePeriod = std::chrono::seconds(1);
    static constexpr auto kFramePollPeriod = std::chrono::milliseconds(5);
    // A job's slices while other jobs wait: a short first one, which streams its first frame
    // (the queue starts the jobs of users with nothing running before it goes on with parked
    // ones: of 40 Position Servo runs of about 8 ms submitted at once on 2 workers, the last
    // one's first frame waits for 20 first slices, not for 20 whole jobs), then longer ones,
    // so that a short job is done in two and a long one switches, and streams a frame, every
    // 10 ms of its running.
    static constexpr auto kFirstSlice = std::chrono::milliseconds(2);
    static constexpr auto kSlice = std::chrono::milliseconds(10);

private:
    // On the job's thread every kProgressInterval steps: limits, events, frames, slice end.
    void onProgress(StartedJob& job, System& root, std::size_t stepsTaken, std::size_t stepsTotal);
    // Initialises the job (prepares it first if needed). False when it has already reached
    // its final state.
    bool start(StartedJob& job);
    // The job's final state after its last slice (ran: whether that slice ended well).
    // endReason: why a component of the model ended the run as designed (a done run's stop
    // reason); empty for a run to its stop time.
    void finishRun(StartedJob& job, bool ran, const std::string& tooLarge, const std::string& endReason = {});
    // A finished run's result: what is stored, and where its last frames come from.
    struct Result {
        const std::string& blob;
        const FrameSource& samples;
    };
    void finish(StartedJob& job, JobState state, const std::string& error, std::uint64_t steps,
                const Result* result);
    // A job stopped for Release or LeaseLost: back to the queue or left to its new holder.
    void giveUp(StartedJob& job);
    // Keeps its model's unpinned runs with results within mLimits.maxUnpinnedRunsPerModel.
    void dropOldResultsOfItsModel(std::int64_t jobId);

    JobStore& mStore;
    JobLeaseStore& mLeases;
    StreamHub& mHub;
    JobLimits mLimits;
    std::chrono::steady_clock::duration mMaxRunTime;   // mLimits.maxWallSeconds
};

// "wall time limit (N s) exceeded"
std::string wallTimeLimitMessage(double seconds);

} // namespace tlmhub::server
