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

JobQueue::JobQueue(JobStore& store, ResultStore& results, StreamHub& hub, JobLimits limits, unsigned workers)
    : mStore(store), mResults(results), mHub(hub), mLimits(limits), mRunner(store, hub, limits),
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
    updateWaiting();
    for (unsigned i = 0; i < mWorkerCount; ++i) mWorkers.emplace_back([this, i] { workerLoop(i); });
}

void JobQueue::shutdown()
{
    {
        std::lock_guard lock(mMutex);
        if (!mStarted) return;
        mStopping = true;
        for (auto& [id, active] : mActive) active.control->requestStop(JobControl::Stop::Shutdown);
        for (auto& [id, study] : mStudies) study->stop(JobState::Interrupted);
    }
    mWake.notify_all();
    for (auto& t : mWorkers) t.join();
    std::unique_lock lock(mMutex);
    mWorkers.clear();
    mStarted = false;
    // Studies that have started end interrupted; the others stay queued in the store.
    std::vector<std::shared_ptr<StudyExecution>> ended;
    while (!mStudies.empty()) {
        std::shared_ptr<StudyExecution> study = mStudies.begin()->second;
        if (study->started()) ended.push_back(study);
        retireStudy(study);
    }
    lock.unlock();
    for (auto& study : ended) study->finalise();
}

void JobQueue::addStudy(std::shared_ptr<StudyExecution> study)
{
    std::unique_lock lock(mMutex);
    OwnerJobs& jobs = mWaiting[study->ownerId()];
    if (jobs.empty()) mRotation.push_back(study->ownerId());
    jobs.studies.push_back(study);
    mStudies.emplace(study->id(), std::move(study));
    updateWaiting();
    lock.unlock();
    mWake.notify_all();
}

bool JobQueue::stopStudy(std::int64_t studyId)
{
    std::unique_lock lock(mMutex);
    const auto found = mStudies.find(studyId);
    if (found == mStudies.end()) return false;
    std::shared_ptr<StudyExecution> study = found->second;
    study->stop(JobState::Cancelled);
    if (!study->complete()) return true;   // the worker of its last run finalises it
    retireStudy(study);
    updateWaiting();
    lock.unlock();
    study->finalise();
    return true;
}

int JobQueue::activeStudies(std::int64_t ownerId)
{
    std::lock_guard lock(mMutex);
    int count = 0;
    for (const auto& [id, study] : mStudies) count += study->ownerId() == ownerId;
    return count;
}

void JobQueue::retireStudy(const std::shared_ptr<StudyExecution>& study)
{
    mStudies.erase(study->id());
    const auto owner = mWaiting.find(study->ownerId());
    if (owner == mWaiting.end()) return;
    auto& studies = owner->second.studies;
    studies.erase(std::remove(studies.begin(), studies.end(), study), studies.end());
    if (owner->second.empty()) {
        mRotation.erase(std::remove(mRotation.begin(), mRotation.end(), owner->first), mRotation.end());
        mWaiting.erase(owner);
    }
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

    const std::size_t stored = mResults.storedBytes(request.ownerId);
    if (stored >= mLimits.maxStoredBytesPerUser) {
        return {std::nullopt, "limit_exceeded",
                "your stored results use " + std::to_string(stored >> 20) + " MiB of " +
                    std::to_string(mLimits.maxStoredBytesPerUser >> 20) +
                    " MiB; delete old jobs (DELETE /api/v1/jobs/{id}) first"};
    }

    std::unique_lock lock(mMutex);
    const auto waiting = mWaiting.find(request.ownerId);
    const std::size_t alreadyQueued = waiting == mWaiting.end() ? 0 : waiting->second.queued.size();
    if (alreadyQueued >= static_cast<std::size_t>(mLimits.maxQueuedPerUser)) {
        return {std::nullopt, "limit_exceeded",
                "you have " + std::to_string(alreadyQueued) + " jobs queued; the limit is " +
                    std::to_string(mLimits.maxQueuedPerUser)};
    }
    const std::int64_t id = mStore.create(request, resolved);
    if (mCompiled.size() < kMaxCompiledQueued) mCompiled.emplace(id, std::move(prepared));
    enqueue(request.ownerId, id);
    updateWaiting();
    lock.unlock();
    mWake.notify_all();
    return {id, {}, {}};
}

JobQueue::CancelRequest JobQueue::requestCancel(std::int64_t jobId)
{
    std::unique_lock lock(mMutex);
    if (removeQueued(jobId)) {
        mCompiled.erase(jobId);
        updateWaiting();
        mStore.finish(jobId, JobState::Cancelled, {}, 0, nullptr);
        lock.unlock();
        mHub.finish(jobId, nullptr, JobState::Cancelled, {});
        return CancelRequest::Cancelled;
    }
    auto active = mActive.find(jobId);
    if (active != mActive.end()) {
        active->second.control->requestStop(JobControl::Stop::Cancel);
        if (active->second.parked) {
            // Its owner's next turn comes first and takes it: its slice ends at once.
            const std::int64_t owner = active->second.ownerId;
            auto& parked = mWaiting.at(owner).parked;
            parked.erase(std::find(parked.begin(), parked.end(), jobId));
            parked.push_front(jobId);
            mRotation.erase(std::find(mRotation.begin(), mRotation.end(), owner));
            mRotation.push_front(owner);
            lock.unlock();
            mWake.notify_one();
        }
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
    {
        // A parked job's subscriber gets what it has logged now, not after the job's next slice
        // (a subscriber of a just submitted job tends to come after its first slice). The lock
        // keeps workers from running it meanwhile.
        std::lock_guard lock(mMutex);
        const auto active = mActive.find(jobId);
        if (active != mActive.end() && active->second.parked) mRunner.publishFrames(*active->second.parked);
    }
    const auto info = mStore.info(jobId);
    if (info && isFinished(info->state)) {
        const auto table = mResults.result(jobId, wanted);
        if (table) {
            TableFrameSource source(*table);
            mHub.finishSubscription(subscription, &source, info->state, info->error);
        } else {
            mHub.finishSubscription(subscription, nullptr, info->state, info->error);
        }
    }
    return subscription;
}

void JobQueue::workerLoop(unsigned worker)
{
    std::unique_lock lock(mMutex);
    for (;;) {
        Work work;
        // When stopping, the workers end the parked jobs (interrupted) before they leave.
        bool picked = false;
        mWake.wait(lock, [&] { return (picked = pickNext(work)) || mStopping; });
        if (!picked) return;
        if (work.kind == Work::Kind::StudyRun) runStudy(worker, work, lock);
        else runJob(work, lock);
        updateWaiting();
        mWake.notify_all();
    }
}

void JobQueue::runJob(Work& work, std::unique_lock<std::mutex>& lock)
{
    const std::int64_t jobId = work.jobId, ownerId = work.ownerId;
    std::unique_ptr<StartedJob> job;
    if (work.kind == Work::Kind::StartJob) {
        std::unique_ptr<PreparedJob> compiled;
        if (auto it = mCompiled.find(jobId); it != mCompiled.end()) {
            compiled = std::move(it->second);
            mCompiled.erase(it);
        }
        if (!mStore.markRunning(jobId)) return;   // no longer queued in the store
        auto control = std::make_shared<JobControl>();
        job = std::make_unique<StartedJob>(jobId, std::move(compiled), control);
        mActive.emplace(jobId, Active{ownerId, std::move(control), nullptr, 0});
        ++mStartedPerOwner[ownerId];
    } else {
        job = std::move(mActive.at(jobId).parked);
    }
    const unsigned threads = jobThreads(!mWaiting.empty(), mActive.size() > 1 || mStudyRunsInFlight > 0);
    updateWaiting();
    lock.unlock();

    const bool finished = mRunner.runSlice(*job, threads, mOthersWaiting);
    if (finished) job.reset();   // its model and logs are freed outside the lock

    lock.lock();
    Active& active = mActive.at(jobId);
    mActiveLogBytes -= active.logBytes;
    if (finished) {
        mActive.erase(jobId);
        if (--mStartedPerOwner[ownerId] <= 0) mStartedPerOwner.erase(ownerId);
        mJobEnded.notify_all();
    } else {
        active.logBytes = job->logBytes();
        mActiveLogBytes += active.logBytes;
        active.parked = std::move(job);
        park(ownerId, jobId);
    }
}

void JobQueue::runStudy(unsigned worker, Work& work, std::unique_lock<std::mutex>& lock)
{
    ++mStudyRunsInFlight;
    updateWaiting();
    lock.unlock();
    work.study->execute(worker, work.run);
    lock.lock();
    --mStudyRunsInFlight;
    // The worker of the last run stores the study's end (a cancelled one's too).
    if (mStudies.count(work.study->id()) && work.study->complete()) {
        retireStudy(work.study);
        lock.unlock();
        work.study->finalise();
        lock.lock();
    }
}

std::size_t JobQueue::compiledQueued()
{
    std::lock_guard lock(mMutex);
    return mCompiled.size();
}

bool JobQueue::canStart(std::int64_t ownerId) const
{
    if (mStopping) return false;
    const auto started = mStartedPerOwner.find(ownerId);
    if (started != mStartedPerOwner.end() && started->second >= mLimits.maxRunningPerUser) return false;
    return mActive.empty() || (mActive.size() < kMaxStartedJobs && mActiveLogBytes < kMaxStartedLogBytes);
}

bool JobQueue::pickNext(Work& work)
{
    // First the users with no job started (the short first slice of their next one, for its
    // first frames), then all in turn.
    for (const bool idleUsersOnly : {true, false}) {
        for (auto it = mRotation.begin(); it != mRotation.end(); ++it) {
            const std::int64_t owner = *it;
            if (idleUsersOnly && mStartedPerOwner.count(owner)) continue;
            OwnerJobs& jobs = mWaiting.at(owner);
            work.ownerId = owner;
            if (!jobs.queued.empty() && canStart(owner)) {
                work.kind = Work::Kind::StartJob;
                work.jobId = jobs.queued.front();
                jobs.queued.pop_front();
            } else if (idleUsersOnly) {
                continue;   // a study's run or a parked job is no first slice
            } else if (!jobs.parked.empty()) {
                work.kind = Work::Kind::ContinueJob;
                work.jobId = jobs.parked.front();
                jobs.parked.pop_front();
            } else if (!takeStudyRun(jobs.studies, work)) {
                continue;
            }
            mRotation.erase(it);
            if (jobs.empty()) mWaiting.erase(owner);
            else mRotation.push_back(owner);   // served: goes to the back of the round
            return true;
        }
    }
    return false;
}

bool JobQueue::takeStudyRun(std::deque<std::shared_ptr<StudyExecution>>& studies, Work& work)
{
    for (std::size_t i = 0; i < studies.size(); ++i) {
        std::shared_ptr<StudyExecution> study = studies.front();
        // The owner's studies take turns too.
        studies.pop_front();
        studies.push_back(study);
        if (mStopping) continue;
        if (auto run = study->take()) {
            work.kind = Work::Kind::StudyRun;
            work.study = std::move(study);
            work.run = std::move(*run);
            return true;
        }
    }
    return false;
}

void JobQueue::updateWaiting()
{
    bool waiting = false;
    for (const auto& [owner, jobs] : mWaiting) {
        if (!jobs.parked.empty() || (!jobs.queued.empty() && canStart(owner)) ||
            std::any_of(jobs.studies.begin(), jobs.studies.end(), [](const auto& study) { return study->hasWork(); })) {
            waiting = true;
            break;
        }
    }
    mOthersWaiting.store(waiting, std::memory_order_relaxed);
}

void JobQueue::enqueue(std::int64_t ownerId, std::int64_t jobId)
{
    OwnerJobs& jobs = mWaiting[ownerId];
    if (jobs.empty()) mRotation.push_back(ownerId);
    jobs.queued.push_back(jobId);
}

void JobQueue::park(std::int64_t ownerId, std::int64_t jobId)
{
    OwnerJobs& jobs = mWaiting[ownerId];
    if (jobs.empty()) mRotation.push_back(ownerId);
    jobs.parked.push_back(jobId);
}

bool JobQueue::removeQueued(std::int64_t jobId)
{
    for (auto it = mWaiting.begin(); it != mWaiting.end(); ++it) {
        auto& fifo = it->second.queued;
        auto pos = std::find(fifo.begin(), fifo.end(), jobId);
        if (pos == fifo.end()) continue;
        fifo.erase(pos);
        if (it->second.empty()) {
            mRotation.erase(std::find(mRotation.begin(), mRotation.end(), it->first));
            mWaiting.erase(it);
        }
        return true;
    }
    return false;
}

bool JobQueue::isQueuedInMemory(std::int64_t jobId) const
{
    for (const auto& [owner, jobs] : mWaiting)
        if (std::find(jobs.queued.begin(), jobs.queued.end(), jobId) != jobs.queued.end()) return true;
    return false;
}

} // namespace tlmhub::server
