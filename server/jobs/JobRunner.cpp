#include "server/jobs/JobRunner.h"

#include "core/Simulation.h"
#include "server/jobs/FrameSource.h"
#include "server/store/ResultBlob.h"
#include "server/store/StoreError.h"

#include <iostream>
#include <sstream>
#include <thread>

namespace tlmhub::server {

namespace {

using Clock = std::chrono::steady_clock;

std::string firstErrorMessage(System& root)
{
    for (const auto& m : root.messages())
        if (m.type == MessageType::Error || m.type == MessageType::Fatal) return m.text;
    return {};
}

std::string resultTooLargeMessage(std::size_t bytes, std::size_t limit)
{
    return "the result (" + std::to_string(bytes) + " bytes) is larger than the limit of " +
           std::to_string(limit) + " bytes; log fewer samples";
}

} // namespace

std::string wallTimeLimitMessage(double seconds)
{
    std::ostringstream os;
    os << "wall time limit (" << seconds << " s) exceeded";
    return os.str();
}

void JobControl::requestStop(Stop reason)
{
    std::lock_guard lock(mMutex);
    Stop none = Stop::None;
    mReason.compare_exchange_strong(none, reason);
    if (mSystem) mSystem->requestStop();
}

void JobControl::attach(System* system)
{
    std::lock_guard lock(mMutex);
    mSystem = system;
}

void JobControl::detach()
{
    std::lock_guard lock(mMutex);
    mSystem = nullptr;
}

StartedJob::StartedJob(const JobLease& lease, std::unique_ptr<PreparedJob> compiled, std::shared_ptr<JobControl> control)
    : mId(lease.jobId), mLease(lease), mJob(std::move(compiled)), mControl(std::move(control))
{
}

// The control must not reach the System after it is gone.
StartedJob::~StartedJob() { mControl->detach(); }

JobRunner::JobRunner(JobStore& store, JobLeaseStore& leases, StreamHub& hub, const JobLimits& limits)
    : mStore(store), mLeases(leases), mHub(hub), mLimits(limits),
      mMaxRunTime(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.maxWallSeconds)))
{
}

void JobRunner::onProgress(StartedJob& job, System& root, std::size_t stepsTaken, std::size_t stepsTotal)
{
    const auto now = Clock::now();
    if (job.mRunTime + (now - job.mSliceStart) > mMaxRunTime) {
        job.mWallTimeExceeded = true;
        root.requestStop();
        return;
    }
    const double progress = stepsTotal ? static_cast<double>(stepsTaken) / static_cast<double>(stepsTotal) : 1.0;
    if (now - job.mLastProgressEvent >= kProgressEventPeriod) {
        job.mLastProgressEvent = now;
        mHub.publishProgress(job.mId, progress);
    }
    if (now - job.mLastProgressStore >= kProgressStorePeriod) {
        job.mLastProgressStore = now;
        // Stored progress is advisory: while the database is away (a restart) the job runs on,
        // and the next period stores it again.
        try {
            mLeases.setProgressLeased(job.mLease, progress);
        } catch (const StoreError& e) {
            if (e.code() != StoreErrc::Unavailable) throw;
        }
    }
    if (now - job.mLastFramePoll >= kFramePollPeriod) {
        job.mLastFramePoll = now;
        mHub.publishFrames(job.mId, *job.mLive);
    }
    if (now - job.mSliceStart >= job.mSliceLength && job.mOthersWaiting->load(std::memory_order_relaxed))
        job.mPause.request_stop();
}

void JobRunner::finish(StartedJob& job, JobState state, const std::string& error, std::uint64_t steps,
                       const Result* result)
{
    // While the database restarts (about a second) the end is stored once it answers again;
    // the lease number keeps a late store from overwriting another node's run. Past the
    // retries the job's lease lapses and the queue gives it to a node again, as it does a
    // stalled node's. A worker thread never ends on a database that is away.
    constexpr auto kRetryPause = std::chrono::milliseconds(250);
    constexpr auto kRetryFor = std::chrono::seconds(5);
    const auto giveUpAt = Clock::now() + kRetryFor;
    for (;;) {
        try {
            if (mLeases.finishLeased(job.mLease, state, error, steps, result ? &result->blob : nullptr)) {
                mHub.finish(job.mId, result ? &result->samples : nullptr, state, error);
                if (result) dropOldResultsOfItsModel(job.mId);
            } else {
                mHub.abandon(job.mId);   // another node took the job over while this one stalled
            }
            return;
        } catch (const StoreError& e) {
            if (e.code() != StoreErrc::Unavailable) throw;
            if (Clock::now() >= giveUpAt) {
                std::cerr << "job " << job.mId << ": its end could not be stored (" << e.what()
                          << "); its lease will lapse and the job run again\n";
                mHub.abandon(job.mId);
                return;
            }
        }
        std::this_thread::sleep_for(kRetryPause);
    }
}

void JobRunner::dropOldResultsOfItsModel(std::int64_t jobId)
{
    try {
        const auto info = mStore.info(jobId);
        if (info && info->modelId) mStore.dropOldResults(*info->modelId, mLimits.maxUnpinnedRunsPerModel);
    } catch (const StoreError& e) {
        // The job's end is stored; the next run of the model drops them.
        std::cerr << "job " << jobId << ": old results of its model not dropped (" << e.what() << ")\n";
    }
}

void JobRunner::giveUp(StartedJob& job)
{
    if (job.mControl->stopReason() == JobControl::Stop::Release) mLeases.release(job.mLease);
    mHub.abandon(job.mId);
}

bool JobRunner::runSlice(StartedJob& job, unsigned threads, const std::atomic<bool>& othersWaiting)
{
    job.mSliceStart = Clock::now();
    try {
        job.mSliceLength = job.mInitialised ? kSlice : kFirstSlice;
        if (!job.mInitialised && !start(job)) return true;
        Simulation& sim = *job.mJob->simulation;
        System& root = sim.system();
        job.mOthersWaiting = &othersWaiting;
        job.mPause = std::stop_source();
        // Automatic threads (a job alone on the server) end by themselves when other
        // processes take a core later and the threads stop paying off.
        RunOptions options;
        options.threads = threads;
        options.progressInterval = kProgressInterval;
        options.progress = [this, &job, &root](std::size_t taken, std::size_t total) {
            onProgress(job, root, taken, total);
        };
        options.pause = job.mPause.get_token();
        const Status ran = sim.run(options);
        // A model that ends its own run (SignalStopSimulation) finishes as designed.
        const bool endedByModel = ran.code() == StatusCode::SimulationEnded;
        const bool ok = ran.isOk() || endedByModel;
        const auto now = Clock::now();
        job.mRunTime += now - job.mSliceStart;
        if (ok && sim.state() == SimulationState::Paused) {
            // Its subscribers see what it has so far while it waits (its first frame, after
            // its first slice).
            job.mLastFramePoll = now;
            mHub.publishFrames(job.mId, *job.mLive);
            return false;
        }
        finishRun(job, ok, {}, endedByModel ? ran.message() : std::string());
    } catch (const std::exception& e) {
        job.mControl->detach();
        // The database went away (a restart) while the job read its request or stored its
        // progress: the job is not at fault. Its lease lapses and the queue runs it again, as
        // when its end cannot be stored (finish).
        if (const auto* store = dynamic_cast<const StoreError*>(&e); store && store->code() == StoreErrc::Unavailable) {
            std::cerr << "job " << job.mId << ": the database is away (" << e.what()
                      << "); its lease will lapse and the job run again\n";
            mHub.abandon(job.mId);
            return true;
        }
        try {
            finish(job, JobState::Failed, std::string("internal error: ") + e.what(), 0, nullptr);
        } catch (const std::exception& storing) {
            std::cerr << "job " << job.mId << ": failed (" << e.what() << ") and that could not be stored ("
                      << storing.what() << "); its lease will lapse\n";
            mHub.abandon(job.mId);
        }
    }
    return true;
}

void JobRunner::publishFrames(StartedJob& job)
{
    if (job.mLive) mHub.publishFrames(job.mId, *job.mLive);
}

bool JobRunner::start(StartedJob& job)
{
    job.mInitialised = true;
    if (!job.mJob) {
        const auto request = mStore.request(job.mId);
        if (!request) {
            finish(job, JobState::Failed, "the stored job request cannot be read", 0, nullptr);
            return false;
        }
        auto prepared = std::make_unique<PreparedJob>();
        PrepareError prepareError;
        if (!prepareJob(*request, mLimits, *prepared, prepareError)) {
            finish(job, JobState::Failed, prepareError.message, 0, nullptr);
            return false;
        }
        job.mJob = std::move(prepared);
    }
    Simulation& sim = *job.mJob->simulation;
    System& root = sim.system();
    job.mControl->attach(&root);
    // The claim stored progress 0 just now; the next store is due a period later (a short
    // job's only progress write would be a wasted transaction).
    job.mLastProgressStore = job.mSliceStart;
    bool ok = sim.initialise().isOk();
    // Initialising clears earlier stop requests; one that came before it is seen here.
    if (job.mControl->stopReason() != JobControl::Stop::None) ok = false;
    if (ok && Clock::now() - job.mSliceStart > mMaxRunTime) {
        job.mWallTimeExceeded = true;
        ok = false;
    }
    if (!ok) {
        finishRun(job, false, {});
        return false;
    }
    job.mLive.emplace(root);
    // Lower bound of the result's size, known before running: fail now, not after.
    const std::size_t estimate = sim.logSlots() * (job.mLive->names().size() + 1) * sizeof(double);
    if (estimate > mLimits.maxResultBytes) {
        finishRun(job, false, resultTooLargeMessage(estimate, mLimits.maxResultBytes));
        return false;
    }
    job.mLogBytes = estimate;
    return true;
}

void JobRunner::finishRun(StartedJob& job, bool ran, const std::string& tooLarge, const std::string& endReason)
{
    job.mControl->detach();
    Simulation& sim = *job.mJob->simulation;
    System& root = sim.system();
    const std::uint64_t steps = root.takenSteps();
    const JobControl::Stop stop = job.mControl->stopReason();
    if (!ran && (stop == JobControl::Stop::Release || stop == JobControl::Stop::LeaseLost)) return giveUp(job);
    JobState finalState = JobState::Done;
    std::string error = endReason;   // of a done run: stored as its stop reason
    if (!tooLarge.empty()) {
        finalState = JobState::Failed;
        error = tooLarge;
    } else if (!ran) {
        switch (stop) {
        case JobControl::Stop::Cancel:
            finalState = JobState::Cancelled;
            break;
        case JobControl::Stop::Shutdown:
            finalState = JobState::Interrupted;
            error = "the server stopped while the job was running";
            break;
        case JobControl::Stop::Release:
        case JobControl::Stop::LeaseLost:
            break;   // handled above
        case JobControl::Stop::None:
            finalState = JobState::Failed;
            if (job.mWallTimeExceeded) {
                error = wallTimeLimitMessage(mLimits.maxWallSeconds);
            } else {
                error = firstErrorMessage(root);
                if (error.empty()) {
                    std::ostringstream os;
                    os << "simulation stopped at t=" << root.time() << " before the stop time " << job.mJob->stop;
                    error = os.str();
                }
            }
            break;
        }
    }
    if (!tooLarge.empty()) return finish(job, finalState, error, steps, nullptr);
    // Whatever was logged is kept, also for stopped runs, as long as it fits. It is stored
    // and its last frames sent straight from the log: no copy as a ResultTable.
    const ResultView logged = sim.results();
    const std::size_t bytes = uncompressedResultBytes(logged);
    if (bytes > mLimits.maxResultBytes) {
        if (finalState == JobState::Done) {
            finalState = JobState::Failed;
            error = resultTooLargeMessage(bytes, mLimits.maxResultBytes);
        }
        return finish(job, finalState, error, steps, nullptr);
    }
    // Each worker thread keeps its buffer: no fresh pages for every result. A rare large
    // result's memory goes back once it is stored.
    constexpr std::size_t kKeptBufferBytes = 16u << 20;
    thread_local std::string blob;
    encodeResult(logged, blob);
    if (!job.mLive) job.mLive.emplace(root);
    const Result result{blob, *job.mLive};
    finish(job, finalState, error, steps, &result);
    if (blob.capacity() > kKeptBufferBytes) std::string().swap(blob);
}

} // namespace tlmhub::server
