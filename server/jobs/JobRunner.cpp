#include "server/jobs/JobRunner.h"

#include "core/Simulation.h"
#include "server/jobs/FrameSource.h"
#include "server/store/ResultBlob.h"

#include <sstream>

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

// What the progress callback needs; lives on the job thread's stack during simulate().
struct JobRunner::RunState {
    JobRunner* runner = nullptr;
    std::int64_t jobId = 0;
    System* root = nullptr;
    const FrameSource* live = nullptr;
    Clock::time_point deadline;
    bool wallTimeExceeded = false;
    Clock::time_point lastProgressEvent{}, lastProgressStore{}, lastFramePoll{};
};

JobRunner::JobRunner(JobStore& store, StreamHub& hub, const JobLimits& limits)
    : mStore(store), mHub(hub), mLimits(limits)
{
}

void JobRunner::onProgress(void* user, std::size_t stepsTaken, std::size_t stepsTotal)
{
    auto& s = *static_cast<RunState*>(user);
    const auto now = Clock::now();
    if (now > s.deadline) {
        s.wallTimeExceeded = true;
        s.root->requestStop();
        return;
    }
    const double progress = stepsTotal ? static_cast<double>(stepsTaken) / static_cast<double>(stepsTotal) : 1.0;
    if (now - s.lastProgressEvent >= kProgressEventPeriod) {
        s.lastProgressEvent = now;
        s.runner->mHub.publishProgress(s.jobId, progress);
    }
    if (now - s.lastProgressStore >= kProgressStorePeriod) {
        s.lastProgressStore = now;
        s.runner->mStore.setProgress(s.jobId, progress);
    }
    if (now - s.lastFramePoll >= kFramePollPeriod) {
        s.lastFramePoll = now;
        s.runner->mHub.publishFrames(s.jobId, *s.live);
    }
}

JobState JobRunner::finish(std::int64_t jobId, JobState state, const std::string& error, std::uint64_t steps,
                           const Result* result)
{
    mStore.finish(jobId, state, error, steps, result ? &result->blob : nullptr);
    mHub.finish(jobId, result ? &result->samples : nullptr, state, error);
    return state;
}

JobState JobRunner::run(std::int64_t jobId, const JobRequest& request, JobControl& control, unsigned threads)
{
    try {
        PreparedJob job;
        PrepareError prepareError;
        if (!prepareJob(request, mLimits, job, prepareError))
            return finish(jobId, JobState::Failed, prepareError.message, 0, nullptr);
        return run(jobId, job, control, threads);
    } catch (const std::exception& e) {
        return finish(jobId, JobState::Failed, std::string("internal error: ") + e.what(), 0, nullptr);
    }
}

JobState JobRunner::run(std::int64_t jobId, PreparedJob& job, JobControl& control, unsigned threads)
{
    const auto started = Clock::now();
    const auto deadline = started + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(mLimits.maxWallSeconds));
    try {
        Simulation& sim = *job.simulation;
        System& root = sim.system();
        // Detached when the run ends, also when something throws.
        struct Detach {
            JobControl& control;
            ~Detach() { control.detach(); }
        } detachOnExit{control};
        control.attach(&root);
        bool ok = sim.initialise().isOk();
        // Initialising clears earlier stop requests; one that came before it is seen here.
        if (control.stopReason() != JobControl::Stop::None) ok = false;
        RunState state;
        state.runner = this;
        state.jobId = jobId;
        state.root = &root;
        state.deadline = deadline;
        // markRunning stored progress 0 just now; the next store is due a period later (a
        // short job's only progress write would be a wasted transaction).
        state.lastProgressStore = started;
        if (ok && Clock::now() > deadline) {
            state.wallTimeExceeded = true;
            ok = false;
        }
        std::string tooLarge;
        if (ok) {
            LiveFrameSource live(root);
            // Lower bound of the result's size, known before running: fail now, not after.
            const std::size_t estimate = sim.logSlots() * (live.names().size() + 1) * sizeof(double);
            if (estimate > mLimits.maxResultBytes) {
                tooLarge = resultTooLargeMessage(estimate, mLimits.maxResultBytes);
                ok = false;
            } else {
                state.live = &live;
                // Automatic threads (a job alone on the server) end by themselves when other
                // processes take a core later and the threads stop paying off.
                RunOptions options;
                options.threads = threads;
                options.progressInterval = kProgressInterval;
                options.progress = [&state](std::size_t taken, std::size_t total) {
                    onProgress(&state, taken, total);
                };
                ok = sim.run(options).isOk();
            }
        }
        control.detach();

        const std::uint64_t steps = root.takenSteps();
        JobState finalState = JobState::Done;
        std::string error;
        if (!tooLarge.empty()) {
            finalState = JobState::Failed;
            error = tooLarge;
        } else if (!ok) {
            switch (control.stopReason()) {
            case JobControl::Stop::Cancel:
                finalState = JobState::Cancelled;
                break;
            case JobControl::Stop::Shutdown:
                finalState = JobState::Interrupted;
                error = "the server stopped while the job was running";
                break;
            case JobControl::Stop::None:
                finalState = JobState::Failed;
                if (state.wallTimeExceeded) {
                    error = wallTimeLimitMessage(mLimits.maxWallSeconds);
                } else {
                    error = firstErrorMessage(root);
                    if (error.empty()) {
                        std::ostringstream os;
                        os << "simulation stopped at t=" << root.time() << " before the stop time " << job.stop;
                        error = os.str();
                    }
                }
                break;
            }
        }
        if (!tooLarge.empty()) return finish(jobId, finalState, error, steps, nullptr);
        // Whatever was logged is kept, also for stopped runs, as long as it fits. It is
        // stored and its last frames sent straight from the log: no copy as a ResultTable.
        const ResultView logged = sim.results();
        const std::size_t bytes = uncompressedResultBytes(logged);
        if (bytes > mLimits.maxResultBytes) {
            if (finalState == JobState::Done) {
                finalState = JobState::Failed;
                error = resultTooLargeMessage(bytes, mLimits.maxResultBytes);
            }
            return finish(jobId, finalState, error, steps, nullptr);
        }
        // Each worker thread keeps its buffer: no fresh pages for every result. A rare large
        // result's memory goes back once it is stored.
        constexpr std::size_t kKeptBufferBytes = 16u << 20;
        thread_local std::string blob;
        encodeResult(logged, blob);
        const Result result{blob, LiveFrameSource(root)};
        const JobState finished = finish(jobId, finalState, error, steps, &result);
        if (blob.capacity() > kKeptBufferBytes) std::string().swap(blob);
        return finished;
    } catch (const std::exception& e) {
        return finish(jobId, JobState::Failed, std::string("internal error: ") + e.what(), 0, nullptr);
    }
}

} // namespace tlmhub::server
