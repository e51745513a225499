#pragma once
// The job queue: compiles and stores submitted jobs, and runs them on a pool of worker
// threads (one worker per job; only a job alone on the server may use more, see jobThreads).
//
// The queue itself is in the database, shared by every node (JobLeaseStore.h): submitting
// stores a queued job and wakes the nodes; a node that runs jobs claims them (fairly between
// users, with the per-user running limit held across nodes), holds a lease on each that its
// pump thread renews, and stores a job's end only while it still holds that lease. The pump
// also re-queues jobs whose node stopped renewing, passes on cancellations asked on other
// nodes, and claims more when workers are free. One node (role all) behaves as it always has.
//
// Time slices (among the jobs this node holds): a worker runs a job for a slice (JobRunner::kSlice) and, when other jobs wait
// for a worker, parks it here and takes the next one, so every job streams its first frames
// soon after it was submitted, not after the jobs before it have finished. A parked job
// stays running (in the store too) and holds its log storage: at most kMaxStartedJobs are
// started at once, and no more start while the started ones' logs take kMaxStartedLogBytes;
// the others wait unstarted.
//
// Fairness: each user has a FIFO of queued jobs and one of parked jobs, and the workers serve
// users round robin: first those with no job started, for the short first slice of their
// next one (its first frames), then all in turn, where a user's turn starts their next
// queued job if they have fewer than JobLimits::maxRunningPerUser started, else goes on with
// their longest parked one. A user with many jobs therefore delays another user's job by at
// most one slice per worker, and a user's first job waits only for the first slices of
// other users' first jobs and the slices running when it came.
//
// Studies (server/studies/StudyExecution.h) share the workers: a study waits in its owner's
// turn behind the owner's jobs and runs one of its runs per turn, on as many workers as take
// it in turn; a user's first job still goes first, so a study of 10,000 runs delays another
// user's job by at most one run.
#include "server/jobs/Job.h"
#include "server/jobs/JobRunner.h"
#include "server/jobs/QueueNode.h"
#include "server/store/JobLeaseStore.h"
#include "server/store/JobStore.h"
#include "server/store/ResultStore.h"
#include "server/jobs/PreparedJob.h"
#include "server/jobs/StreamHub.h"
#include "server/studies/StudyExecution.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
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
    JobQueue(JobStore& store, JobLeaseStore& leases, ResultStore& results, StreamHub& hub, JobLimits limits,
             unsigned workers, QueueNode node = {});
    ~JobQueue();   // shutdown()
    JobQueue(const JobQueue&) = delete;
    JobQueue& operator=(const JobQueue&) = delete;

    // Starts the workers and the pump, which claims the stored queued jobs (a restart continues
    // where the last run stopped; jobs a crashed node held come back when their leases expire).
    void start();
    // Stops started jobs, parked ones too (they become interrupted, or go back to the queue
    // when QueueNode::releaseOnShutdown), joins the workers. Queued jobs stay queued.
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
    // Beyond this many, a queued job keeps only its stored request (the oldest compiled ones
    // are dropped: they may have gone to other nodes): memory stays bounded.
    static constexpr std::size_t kMaxCompiledQueued = 256;

    // Never waits: a queued job is cancelled at once; a started one is asked to stop (a parked
    // one is the next a worker takes), and its event.done (cancelled) follows when it has. A
    // job running on another node is marked; that node stops it at its pump's next round.
    // NotActive: neither queued nor started.
    enum class CancelRequest { NotActive, Cancelled, Cancelling };
    CancelRequest requestCancel(std::int64_t jobId);
    // The same, and for a running job the call waits (10 s at most) until the job has
    // reached its final state. False if the job is not queued or running.
    bool cancel(std::int64_t jobId);

    // Subscribe to a job's events (see StreamHub). A job that has already finished gets one
    // frame with its whole result and event.done at once, on the calling thread.
    std::uint64_t subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate,
                            StreamSink sink);

    // Queues a study (its first run marks it running). Runs continue until its plan is done
    // or stopStudy; then a worker stores its final state.
    void addStudy(std::shared_ptr<StudyExecution> study);
    // Cancels a queued or running study; false when it is not active here. Its final state is
    // stored at once when no run is in flight, else when the last one has stopped.
    bool stopStudy(std::int64_t studyId);

    JobStore& store() { return mStore; }
    JobLeaseStore& leases() { return mLeases; }
    const QueueNode& node() const { return mNode; }
    ResultStore& results() { return mResults; }
    StreamHub& hub() { return mHub; }
    const JobLimits& limits() const { return mLimits; }

    // Jobs started at once (running or parked): a lab of 40 streams all its runs together.
    static constexpr std::size_t kMaxStartedJobs = 64;
    // Log storage of the started jobs beyond which no other starts (Position Servo: 2 MB).
    static constexpr std::size_t kMaxStartedLogBytes = std::size_t(1) << 30;

private:
    // What a worker takes next: a job to start or to continue, or a run of a study.
    struct Work {
        // EndStudy: a study with nothing left to run and none in flight (a resumed one whose
        // remaining runs were all stored) is finalised by the worker that found it so.
        enum class Kind { StartJob, ContinueJob, StudyRun, EndStudy } kind = Kind::StartJob;
        std::int64_t jobId = 0, ownerId = 0;
        std::shared_ptr<StudyExecution> study;
        PlannedRun run;
    };
    void workerLoop(unsigned worker);
    // The pump: renews leases, re-queues expired ones, passes on cancellations, claims jobs.
    void pumpLoop();
    // Wakes the pump when another node (or this one) says there is work (NOTIFY).
    void listenLoop();
    void pokePump();                        // caller must not hold mMutex
    void claimJobs();
    void renewLeases();
    void expireLeases();
    void applyCancels();
    // Asks a started job to stop; a parked one is the next its owner's turn takes.
    void stopStarted(std::int64_t jobId, JobControl::Stop reason);   // caller holds mMutex
    // Runs `step` (store calls); a store error is reported once per series, not thrown.
    void pumpStep(const char* what, const std::function<void()>& step);
    // Keeps a compiled job for when this node claims it; drops the oldest beyond the bound.
    void keepCompiled(std::int64_t jobId, std::unique_ptr<PreparedJob> prepared);   // holds mMutex
    void runJob(Work& work, std::unique_lock<std::mutex>& lock);
    void runStudy(unsigned worker, Work& work, std::unique_lock<std::mutex>& lock);
    // Retires and finalises the study once if it is complete (caller holds `lock`).
    void endStudyIfComplete(const std::shared_ptr<StudyExecution>& study, std::unique_lock<std::mutex>& lock);
    // Next work by the fairness rule. Caller holds mMutex.
    bool pickNext(Work& work);
    // A run of one of the owner's studies, if one has a run ready. Caller holds mMutex.
    bool takeStudyRun(std::deque<std::shared_ptr<StudyExecution>>& studies, Work& work);
    // Removes a study that has nothing left to run from the queue. Caller holds mMutex.
    void retireStudy(const std::shared_ptr<StudyExecution>& study);
    bool canStart(std::int64_t ownerId) const;                   // caller holds mMutex
    // Whether a job waits that a worker could take; what a running slice checks.
    void updateWaiting();                                        // caller holds mMutex
    void enqueue(std::int64_t ownerId, std::int64_t jobId);     // caller holds mMutex
    void park(std::int64_t ownerId, std::int64_t jobId);        // caller holds mMutex
    bool removeQueued(std::int64_t jobId);                      // caller holds mMutex
    Submitted queue(const JobRequest& request, std::unique_ptr<PreparedJob> prepared);

    // A user's jobs waiting for a worker.
    struct OwnerJobs {
        std::deque<std::int64_t> queued;   // claimed by this node, not started, FIFO
        std::deque<std::int64_t> parked;   // started, between slices, FIFO
        std::deque<std::shared_ptr<StudyExecution>> studies;   // queued or running, in turn
        bool empty() const { return queued.empty() && parked.empty() && studies.empty(); }
    };
    // A started job: running a slice on a worker, or parked (then `parked` holds it).
    struct Active {
        std::int64_t ownerId = 0;
        std::shared_ptr<JobControl> control;
        std::unique_ptr<StartedJob> parked;
        std::size_t logBytes = 0;
    };

    JobStore& mStore;
    JobLeaseStore& mLeases;
    ResultStore& mResults;
    StreamHub& mHub;
    JobLimits mLimits;
    JobRunner mRunner;
    unsigned mWorkerCount;
    QueueNode mNode;

    std::mutex mMutex;
    std::condition_variable mWake;       // a job was queued or parked, a worker freed, or stopping
    std::condition_variable mJobEnded;   // a started job reached its final state
    std::map<std::int64_t, OwnerJobs> mWaiting;    // owners with queued or parked jobs
    std::deque<std::int64_t> mRotation;            // those owners, next first
    std::map<std::int64_t, int> mStartedPerOwner;
    std::map<std::int64_t, JobLease> mHeld;        // claimed here: queued here or started
    std::map<std::int64_t, Active> mActive;        // started jobs
    std::size_t mActiveLogBytes = 0;
    std::atomic<bool> mOthersWaiting{false};
    std::map<std::int64_t, std::unique_ptr<PreparedJob>> mCompiled;   // queued job -> compiled
    std::deque<std::int64_t> mCompiledOrder;                           // oldest first
    std::map<std::int64_t, std::shared_ptr<StudyExecution>> mStudies;  // queued or running
    std::size_t mStudyRunsInFlight = 0;
    std::vector<std::thread> mWorkers;
    std::thread mPump, mListener;
    std::condition_variable mPumpWake;
    bool mPumpPoked = false;
    bool mPumpFailing = false;   // the last store call of the pump failed (reported once)
    bool mStarted = false;
    bool mStopping = false;
};

} // namespace tlmhub::server
