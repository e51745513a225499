#include "server/jobs/JobQueue.h"

#include "server/jobs/FrameSource.h"
#include "server/jobs/PreparedJob.h"

#include "core/Simulation.h"

#include <algorithm>

namespace tlmhub::server {

unsigned jobThreads(bool otherJobsQueued, bool otherJobsRunning)
{
    return otherJobsQueued || otherJobsRunning ? 1 : RunOptions::autoThreads;
}

JobQueue::JobQueue(JobStore& store, StreamHub& hub, JobLimits limits, unsigned workers)
    : mStore(store), mHub(hub), mLimits(limits), mRunner(store, hub, limits),
      mWorkerCount(std::max(1u, workers))
{
}

JobQueue::~JobQueue() { shutdown(); }

void JobQueue::start()
{
    std::lock_guard lock(mMutex);
    if (mStarted) return;
    mStarted = true;
    mStopping = false;
    mStore.markRunningInterrupted();
    for (const JobInfo& job : mStore.listInState(JobState::Queued))
        if (!isQueuedInMemory(job.id)) enqueue(job.ownerId, job.id);
    for (unsigned i = 0; i < mWorkerCount; ++i) mWorkers.emplace_back([this] { workerLoop(); });
}

void JobQueue::shutdown()
{
    {
        std::lock_guard lock(mMutex);
        if (!mStarted) return;
        mStopping = true;
        for (auto& [id, control] : mActive) control->requestStop(JobControl::Stop::Shutdown);
    }
    mWake.notify_all();
    for (auto& t : mWorkers) t.join();
    std::lock_guard lock(mMutex);
    mWorkers.clear();
    mStarted = false;
}

JobQueue::Submitted JobQueue::submit(const JobRequest& request)
{
    auto prepared = std::make_unique<PreparedJob>();
    PrepareError error;
    if (!prepareJob(request, mLimits, *prepared, error)) return {std::nullopt, error.code, error.message};
    return queue(request, std::move(prepared));
}

JobQueue::Submitted JobQueue::submit(const JobRequest& request, Model model)
{
    auto prepared = std::make_unique<PreparedJob>();
    PrepareError error;
    if (!prepareJob(request, std::move(model), mLimits, *prepared, error))
        return {std::nullopt, error.code, error.message};
    return queue(request, std::move(prepared));
}

JobQueue::Submitted JobQueue::queue(const JobRequest& request, std::unique_ptr<PreparedJob> prepared)
{
    JobInfo resolved;
    resolved.start = prepared->start;
    resolved.step = prepared->step;
    resolved.stop = prepared->stop;
    resolved.logSamples = prepared->logSamples;
    resolved.steps = prepared->steps;

    const std::size_t stored = mStore.storedBytes(request.ownerId);
    if (stored >= mLimits.maxStoredBytesPerUser) {
        return {std::nullopt, "limit_exceeded",
                "your stored results use " + std::to_string(stored >> 20) + " MiB of " +
                    std::to_string(mLimits.maxStoredBytesPerUser >> 20) +
                    " MiB; delete old jobs (DELETE /api/v1/jobs/{id}) first"};
    }

    std::unique_lock lock(mMutex);
    const auto queued = mQueued.find(request.ownerId);
    const std::size_t alreadyQueued = queued == mQueued.end() ? 0 : queued->second.size();
    if (alreadyQueued >= static_cast<std::size_t>(mLimits.maxQueuedPerUser)) {
        return {std::nullopt, "limit_exceeded",
                "you have " + std::to_string(alreadyQueued) + " jobs queued; the limit is " +
                    std::to_string(mLimits.maxQueuedPerUser)};
    }
    const std::int64_t id = mStore.create(request, resolved);
    if (mCompiled.size() < kMaxCompiledQueued) mCompiled.emplace(id, std::move(prepared));
    enqueue(request.ownerId, id);
    lock.unlock();
    mWake.notify_all();
    return {id, {}, {}};
}

JobQueue::CancelRequest JobQueue::requestCancel(std::int64_t jobId)
{
    std::unique_lock lock(mMutex);
    if (removeQueued(jobId)) {
        mCompiled.erase(jobId);
        mStore.finish(jobId, JobState::Cancelled, {}, 0, nullptr);
        lock.unlock();
        mHub.finish(jobId, nullptr, JobState::Cancelled, {});
        return CancelRequest::Cancelled;
    }
    auto active = mActive.find(jobId);
    if (active != mActive.end()) {
        active->second->requestStop(JobControl::Stop::Cancel);
        return CancelRequest::Cancelling;
    }
    // Queued in the store but not (yet) here: the queue has not been started.
    const auto info = mStore.info(jobId);
    if (info && info->state == JobState::Queued &&
        mStore.finish(jobId, JobState::Cancelled, {}, 0, nullptr)) {
        lock.unlock();
        mHub.finish(jobId, nullptr, JobState::Cancelled, {});
        return CancelRequest::Cancelled;
    }
    return CancelRequest::NotActive;
}

bool JobQueue::cancel(std::int64_t jobId)
{
    const CancelRequest request = requestCancel(jobId);
    if (request == CancelRequest::Cancelling) {
        // The loop checks for a stop every step; initialize() is the longest wait.
        std::unique_lock lock(mMutex);
        mJobEnded.wait_for(lock, std::chrono::seconds(10), [&] { return mActive.count(jobId) == 0; });
    }
    return request != CancelRequest::NotActive;
}

std::uint64_t JobQueue::subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate,
                                  StreamSink sink)
{
    // Subscribe first, then look at the state: the runner stores the final state before it
    // ends the job's subscriptions, so either it serves this subscription or we do, once.
    const std::vector<std::string> wanted = variables;
    const std::uint64_t subscription = mHub.subscribe(jobId, std::move(variables), rate, std::move(sink));
    const auto info = mStore.info(jobId);
    if (info && isFinished(info->state)) {
        const auto table = mStore.result(jobId, wanted);
        if (table) {
            TableFrameSource source(*table);
            mHub.finishSubscription(subscription, &source, info->state, info->error);
        } else {
            mHub.finishSubscription(subscription, nullptr, info->state, info->error);
        }
    }
    return subscription;
}

void JobQueue::workerLoop()
{
    std::unique_lock lock(mMutex);
    for (;;) {
        std::int64_t jobId = 0, ownerId = 0;
        mWake.wait(lock, [&] { return mStopping || pickNext(jobId, ownerId); });
        if (mStopping) return;
        const unsigned threads = jobThreads(!mQueued.empty(), !mActive.empty());
        auto control = std::make_shared<JobControl>();
        std::unique_ptr<PreparedJob> compiled;
        if (auto it = mCompiled.find(jobId); it != mCompiled.end()) {
            compiled = std::move(it->second);
            mCompiled.erase(it);
        }
        const bool marked = mStore.markRunning(jobId);
        if (marked) mActive.emplace(jobId, control);
        lock.unlock();

        if (marked) {
            const auto request = compiled ? std::nullopt : mStore.request(jobId);
            if (compiled) {
                mRunner.run(jobId, *compiled, *control, threads);
            } else if (request) {
                mRunner.run(jobId, *request, *control, threads);
            } else {
                mStore.finish(jobId, JobState::Failed, "the stored job request cannot be read", 0, nullptr);
                mHub.finish(jobId, nullptr, JobState::Failed, "the stored job request cannot be read");
            }
        }

        lock.lock();
        mActive.erase(jobId);
        if (--mRunningPerOwner[ownerId] <= 0) mRunningPerOwner.erase(ownerId);
        mJobEnded.notify_all();
        mWake.notify_all();
    }
}

std::size_t JobQueue::compiledQueued()
{
    std::lock_guard lock(mMutex);
    return mCompiled.size();
}

bool JobQueue::pickNext(std::int64_t& jobId, std::int64_t& ownerId)
{
    for (auto it = mRotation.begin(); it != mRotation.end(); ++it) {
        const std::int64_t owner = *it;
        auto running = mRunningPerOwner.find(owner);
        if (running != mRunningPerOwner.end() && running->second >= mLimits.maxRunningPerUser) continue;
        auto& fifo = mQueued[owner];
        jobId = fifo.front();
        ownerId = owner;
        fifo.pop_front();
        mRotation.erase(it);
        if (fifo.empty()) mQueued.erase(owner);
        else mRotation.push_back(owner);   // served: goes to the back of the round
        ++mRunningPerOwner[owner];
        return true;
    }
    return false;
}

void JobQueue::enqueue(std::int64_t ownerId, std::int64_t jobId)
{
    auto& fifo = mQueued[ownerId];
    if (fifo.empty()) mRotation.push_back(ownerId);
    fifo.push_back(jobId);
}

bool JobQueue::removeQueued(std::int64_t jobId)
{
    for (auto it = mQueued.begin(); it != mQueued.end(); ++it) {
        auto& fifo = it->second;
        auto pos = std::find(fifo.begin(), fifo.end(), jobId);
        if (pos == fifo.end()) continue;
        fifo.erase(pos);
        if (fifo.empty()) {
            mRotation.erase(std::find(mRotation.begin(), mRotation.end(), it->first));
            mQueued.erase(it);
        }
        return true;
    }
    return false;
}

bool JobQueue::isQueuedInMemory(std::int64_t jobId) const
{
    for (const auto& [owner, fifo] : mQueued)
        if (std::find(fifo.begin(), fifo.end(), jobId) != fifo.end()) return true;
    return false;
}

} // namespace tlmhub::server
