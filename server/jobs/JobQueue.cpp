#include "server/jobs/JobQueue.h"
#include "server/jobs/StorageQuota.h"

#include "server/jobs/FrameSource.h"
#include "server/jobs/PreparedJob.h"

#include "core/Simulation.h"
#include "server/store/StoreError.h"

#include <algorithm>
#include <iostream>

namespace tlmhub::server {

unsigned jobThreads(bool otherJobsQueued, bool otherJobsRunning)
{
    return otherJobsQueued || otherJobsRunning ? 1 : RunOptions::autoThreads;
}

JobQueue::JobQueue(JobStore& store, JobLeaseStore& leases, ResultStore& results, StreamHub& hub, JobLimits limits,
                   unsigned workers, QueueNode node)
    : mStore(store), mLeases(leases), mResults(results), mHub(hub), mLimits(limits),
      mRunner(store, leases, hub, limits), mWorkerCount(std::max(1u, workers)), mNode(std::move(node))
{
}

JobQueue::~JobQueue() { shutdown(); }

void JobQueue::start()
{
    std::lock_guard lock(mMutex);
    if (mStarted) return;
    mStarted = true;
    mStopping = false;
    mPumpPoked = true;   // claims what is queued at once
    for (unsigned i = 0; i < mWorkerCount; ++i) mWorkers.emplace_back([this, i] { workerLoop(i); });
    mPump = std::thread([this] { pumpLoop(); });
    mListener = std::thread([this] { listenLoop(); });
}

void JobQueue::shutdown()
{
    {
        std::lock_guard lock(mMutex);
        if (!mStarted) return;
        mStopping = true;
        const auto reason = mNode.releaseOnShutdown ? JobControl::Stop::Release : JobControl::Stop::Shutdown;
        for (auto& [id, active] : mActive) active.control->requestStop(reason);
        for (auto& [id, study] : mStudies) study->stop(JobState::Interrupted);
    }
    mWake.notify_all();
    mPumpWake.notify_all();
    mLeases.interruptWait();
    mPump.join();
    mListener.join();
    for (auto& t : mWorkers) t.join();
    std::unique_lock lock(mMutex);
    mWorkers.clear();
    mStarted = false;
    // Claimed jobs that never started go back to the queue, for this node's next start or
    // another node.
    std::vector<JobLease> unstarted;
    for (const auto& [id, lease] : mHeld) unstarted.push_back(lease);
    mHeld.clear();
    for (const JobLease& lease : unstarted) removeQueued(lease.jobId);
    lock.unlock();
    for (const JobLease& lease : unstarted) {
        try {
            mLeases.release(lease);
        } catch (const std::exception&) {
            // Its lease expires instead.
        }
    }
    lock.lock();
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
        return {std::nullopt, "limit_exceeded", quotaMessage(stored, mLimits.maxStoredBytesPerUser)};
    }

    // Stored with what the run will use, for its model's run history.
    JobRequest withUsedValues = request;
    withUsedValues.usedParameters = std::move(prepared->usedParameters);
    // Queued on every node together; jobs claimed by a node count as running.
    const JobStore::Admission admission = mStore.createWithinQueueLimit(withUsedValues, resolved, mLimits.maxQueuedPerUser);
    if (!admission.id) {
        // Temporary: room comes as the user's jobs start.
        return {std::nullopt, "rate_limited",
                "you have " + std::to_string(admission.queued) + " jobs queued; the limit is " +
                    std::to_string(mLimits.maxQueuedPerUser) + " (--max-queued-per-user): try again when one has started"};
    }
    const std::int64_t id = *admission.id;
    if (mNode.runsJobs) {
        std::lock_guard lock(mMutex);
        keepCompiled(id, std::move(prepared));
    }
    mLeases.notifyWork();
    pokePump();
    return {id, {}, {}};
}

void JobQueue::keepCompiled(std::int64_t jobId, std::unique_ptr<PreparedJob> prepared)
{
    // Ids of jobs that have started since are dropped from the order now and then.
    if (mCompiledOrder.size() > 2 * kMaxCompiledQueued) {
        std::erase_if(mCompiledOrder, [this](std::int64_t id) { return !mCompiled.count(id); });
    }
    while (mCompiled.size() >= kMaxCompiledQueued && !mCompiledOrder.empty()) {
        mCompiled.erase(mCompiledOrder.front());
        mCompiledOrder.pop_front();
    }
    mCompiled.emplace(jobId, std::move(prepared));
    mCompiledOrder.push_back(jobId);
}

JobQueue::CancelRequest JobQueue::requestCancel(std::int64_t jobId)
{
    std::unique_lock lock(mMutex);
    const auto held = mHeld.find(jobId);
    if (held != mHeld.end() && removeQueued(jobId)) {
        // Claimed here, not started.
        const JobLease lease = held->second;
        mHeld.erase(held);
        mCompiled.erase(jobId);
        updateWaiting();
        lock.unlock();
        const bool stored = mLeases.finishLeased(lease, JobState::Cancelled, {}, 0, nullptr);
        pokePump();
        if (!stored) return CancelRequest::NotActive;
        mHub.finish(jobId, nullptr, JobState::Cancelled, {});
        return CancelRequest::Cancelled;
    }
    if (mActive.count(jobId)) {
        stopStarted(jobId, JobControl::Stop::Cancel);
        return CancelRequest::Cancelling;
    }
    lock.unlock();
    // Queued in the store (on no node yet), or running on another node.
    switch (mLeases.requestCancel(jobId)) {
    case JobLeaseStore::CancelOutcome::Cancelled:
        lock.lock();
        mCompiled.erase(jobId);   // a job submitted here, not claimed yet
        lock.unlock();
        mHub.finish(jobId, nullptr, JobState::Cancelled, {});
        return CancelRequest::Cancelled;
    case JobLeaseStore::CancelOutcome::Cancelling:
        return CancelRequest::Cancelling;
    case JobLeaseStore::CancelOutcome::NotActive:
        break;
    }
    return CancelRequest::NotActive;
}

void JobQueue::stopStarted(std::int64_t jobId, JobControl::Stop reason)
{
    Active& active = mActive.at(jobId);
    active.control->requestStop(reason);
    if (!active.parked) return;
    // Its owner's next turn comes first and takes it: its slice ends at once.
    const std::int64_t owner = active.ownerId;
    auto& parked = mWaiting.at(owner).parked;
    parked.erase(std::find(parked.begin(), parked.end(), jobId));
    parked.push_front(jobId);
    mRotation.erase(std::find(mRotation.begin(), mRotation.end(), owner));
    mRotation.push_front(owner);
    mWake.notify_one();
}

bool JobQueue::cancel(std::int64_t jobId)
{
    const CancelRequest request = requestCancel(jobId);
    if (request != CancelRequest::Cancelling) return request != CancelRequest::NotActive;
    // The loop checks for a stop every step; initialize() is the longest wait.
    constexpr auto kWait = std::chrono::seconds(10);
    std::unique_lock lock(mMutex);
    if (mActive.count(jobId)) {
        mJobEnded.wait_for(lock, kWait, [&] { return mActive.count(jobId) == 0; });
        return true;
    }
    lock.unlock();
    // On another node: its pump sees the request within a poll period.
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    while (std::chrono::steady_clock::now() < deadline) {
        const auto info = mStore.info(jobId);
        if (!info || isFinished(info->state)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
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
        else if (work.kind == Work::Kind::EndStudy) endStudyIfComplete(work.study, lock);
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
        auto control = std::make_shared<JobControl>();
        job = std::make_unique<StartedJob>(mHeld.at(jobId), std::move(compiled), control);
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
        mHeld.erase(jobId);
        if (--mStartedPerOwner[ownerId] <= 0) mStartedPerOwner.erase(ownerId);
        mJobEnded.notify_all();
        mPumpPoked = true;   // room for another claim
        mPumpWake.notify_one();
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
    endStudyIfComplete(work.study, lock);
}

void JobQueue::endStudyIfComplete(const std::shared_ptr<StudyExecution>& study, std::unique_lock<std::mutex>& lock)
{
    if (!mStudies.count(study->id()) || !study->complete()) return;
    retireStudy(study);
    lock.unlock();
    study->finalise();
    lock.lock();
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
        if (study->started() && study->complete()) {
            work.kind = Work::Kind::EndStudy;
            work.study = std::move(study);
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

void JobQueue::pokePump()
{
    {
        std::lock_guard lock(mMutex);
        mPumpPoked = true;
    }
    mPumpWake.notify_one();
}

void JobQueue::listenLoop()
{
    for (;;) {
        {
            std::lock_guard lock(mMutex);
            if (mStopping) return;
        }
        if (mLeases.waitForWork(mNode.pollPeriod)) pokePump();
    }
}

void JobQueue::pumpLoop()
{
    using Clock = std::chrono::steady_clock;
    Clock::time_point nextRenewal = Clock::now(), nextPoll = Clock::now();
    std::unique_lock lock(mMutex);
    while (!mStopping) {
        mPumpWake.wait_until(lock, std::min(nextRenewal, nextPoll), [&] { return mPumpPoked || mStopping; });
        if (mStopping) break;
        mPumpPoked = false;
        lock.unlock();
        const auto now = Clock::now();
        if (now >= nextRenewal) {
            pumpStep("renewing leases", [this] { renewLeases(); });
            nextRenewal = now + mNode.leaseTime / 3;
        }
        if (now >= nextPoll) {
            pumpStep("re-queuing jobs of stopped nodes", [this] { expireLeases(); });
            nextPoll = now + mNode.pollPeriod;
        }
        pumpStep("checking for cancellations", [this] { applyCancels(); });
        pumpStep("claiming jobs", [this] { claimJobs(); });
        lock.lock();
    }
}

void JobQueue::pumpStep(const char* what, const std::function<void()>& step)
{
    try {
        step();
        if (mPumpFailing) std::cerr << "job queue: the database answers again\n";
        mPumpFailing = false;
    } catch (const std::exception& e) {
        // The database may be restarting: the next round tries again; jobs held here keep
        // running, and their leases are renewed once it is back (if they have not expired).
        if (!mPumpFailing) std::cerr << "job queue: " << what << " failed: " << e.what() << "\n";
        mPumpFailing = true;
    }
}

void JobQueue::claimJobs()
{
    if (!mNode.runsJobs) return;
    std::size_t held = 0;
    {
        std::lock_guard lock(mMutex);
        if (mStopping) return;
        held = mHeld.size();
    }
    ClaimRequest request{mNode.id, 0, mLimits.maxRunningPerUser, mNode.leaseTime, false};
    std::vector<JobLease> claimed;
    // Any user's jobs while workers would otherwise be free; then the first jobs of users with
    // nothing running anywhere (their first slice) up to the larger bound.
    if (held < mNode.heldLimit) {
        request.count = mNode.heldLimit - held;
        claimed = mLeases.claim(request);
        held += claimed.size();
    }
    if (held < mNode.firstSliceHeldLimit) {
        request.count = mNode.firstSliceHeldLimit - held;
        request.idleOwnersOnly = true;
        for (const JobLease& lease : mLeases.claim(request)) claimed.push_back(lease);
    }
    if (claimed.empty()) return;
    {
        std::lock_guard lock(mMutex);
        for (const JobLease& lease : claimed) {
            mHeld.emplace(lease.jobId, lease);
            enqueue(lease.ownerId, lease.jobId);
        }
        updateWaiting();
    }
    mWake.notify_all();
}

void JobQueue::renewLeases()
{
    std::vector<JobLease> held;
    {
        std::lock_guard lock(mMutex);
        for (const auto& [id, lease] : mHeld) held.push_back(lease);
    }
    mLeases.touchNode(NodeInfo{mNode.id, mNode.role, mNode.address, 0});
    if (held.empty()) return;
    const std::vector<std::int64_t> lost = mLeases.renew(mNode.id, held, mNode.leaseTime);
    std::lock_guard lock(mMutex);
    for (const std::int64_t id : lost) {
        if (!mHeld.count(id)) continue;   // it ended meanwhile
        if (removeQueued(id)) {
            mHeld.erase(id);
            mCompiled.erase(id);
        } else if (mActive.count(id)) {
            stopStarted(id, JobControl::Stop::LeaseLost);
        }
    }
    updateWaiting();
}

void JobQueue::expireLeases()
{
    for (const ExpiredLease& expired : mLeases.expireLeases(mNode.maxAttempts, mNode.backoff, mNode.maxBackoff)) {
        if (expired.state == JobState::Queued) continue;
        const auto info = mStore.info(expired.jobId);
        mHub.finish(expired.jobId, nullptr, expired.state, info ? info->error : std::string());
    }
}

void JobQueue::applyCancels()
{
    std::vector<std::int64_t> held;
    {
        std::lock_guard lock(mMutex);
        for (const auto& [id, lease] : mHeld) held.push_back(id);
    }
    if (held.empty()) return;
    std::vector<JobLease> unstarted;
    {
        const std::vector<std::int64_t> cancelled = mLeases.cancelRequested(held);
        std::lock_guard lock(mMutex);
        for (const std::int64_t id : cancelled) {
            const auto lease = mHeld.find(id);
            if (lease == mHeld.end()) continue;   // it ended meanwhile
            if (mActive.count(id)) {
                stopStarted(id, JobControl::Stop::Cancel);
            } else if (removeQueued(id)) {
                unstarted.push_back(lease->second);
                mHeld.erase(lease);
                mCompiled.erase(id);
            }
        }
        updateWaiting();
    }
    for (const JobLease& lease : unstarted)
        if (mLeases.finishLeased(lease, JobState::Cancelled, {}, 0, nullptr))
            mHub.finish(lease.jobId, nullptr, JobState::Cancelled, {});
}

} // namespace tlmhub::server
