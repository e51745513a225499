#pragma once
// The job queue as the database holds it, shared by every node of a deployment (docs/scale-out.md).
// A worker node claims queued jobs; a claim sets the job running with a lease: the node that
// holds it, an expiry it renews while the job runs, and a lease number (the fencing token) that
// grows by one at every claim. Only the holder of the current lease number may store the job's
// end, so a worker paused past its lease (SIGSTOP) and resumed cannot store a result after
// another worker has taken the job over. A lease that expires (its node died or stalled) puts the
// job back in the queue after a backoff, until it has been claimed maxAttempts times: then it
// is dead, with the reason.
//
// Nodes register themselves (id, role, the address other nodes reach them at) and say they are
// alive; a job's lease names its node, so an API node finds where a running job streams from.
//
// Times are the database's clock on PostgreSQL (nodes on several machines agree on it) and
// the local clock on SQLite (one machine). Both back ends claim in one transaction that
// serialises claims (PostgreSQL: an advisory transaction lock, then rows FOR UPDATE SKIP
// LOCKED; SQLite: BEGIN IMMEDIATE), so per-user limits hold across all nodes.
#include "server/jobs/Job.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

// A claimed job: who owns it and the lease number its node must show to store its end.
struct JobLease {
    std::int64_t jobId = 0;
    std::int64_t ownerId = 0;
    std::int64_t lease = 0;   // fencing token: 1 at the first claim, +1 at each later one
};

struct ClaimRequest {
    std::string nodeId;
    std::size_t count = 1;                   // claim at most this many
    int maxRunningPerUser = 2;               // running jobs of one user on all nodes together
    std::chrono::milliseconds leaseTime{10'000};
    // Only jobs of users with no job running anywhere (their first slice: see JobQueue.h).
    bool idleOwnersOnly = false;
};

// What expireLeases did to one job.
struct ExpiredLease {
    std::int64_t jobId = 0;
    // Queued again; Dead (claimed maxAttempts times); or Cancelled, when its cancellation had
    // been asked (a job queued again would lose that request at its next claim).
    JobState state = JobState::Queued;
};

struct LeaseHolder {
    std::string nodeId;
    std::string address;   // the node's registered address ("" if the node is not registered)
    std::int64_t lease = 0;
};

struct NodeInfo {
    std::string id;        // unique per process start
    std::string role;      // "api", "worker" or "all"
    std::string address;   // "http://host:port" other nodes reach it at; may be empty
    std::int64_t lastSeenMillis = 0;
};

class JobLeaseStore {
public:
    virtual ~JobLeaseStore() = default;

    // Claims queued jobs whose backoff has passed, fairly between users: a user's k-th queued
    // job (oldest first) counts as their (running + k)-th, and jobs go in the order of that
    // count, then of the user's latest claim (the user served longest ago first: round robin),
    // then of id; a user never gets more than maxRunningPerUser running. Sets state
    // running, started_at (first claim only), progress 0, the lease (node, expiry, number+1),
    // clears a cancel request. Returns the claimed jobs in that order.
    virtual std::vector<JobLease> claim(const ClaimRequest& request) = 0;

    // Extends the leases the node still holds (same node and lease number, still running).
    // Returns the ids of those it no longer holds: the node must stop them without storing.
    virtual std::vector<std::int64_t> renew(const std::string& nodeId, const std::vector<JobLease>& leases,
                                            std::chrono::milliseconds leaseTime) = 0;

    // Ids among `jobIds` (running jobs) whose cancellation was asked (requestCancel).
    virtual std::vector<std::int64_t> cancelRequested(const std::vector<std::int64_t>& jobIds) = 0;

    enum class CancelOutcome { NotActive, Cancelled, Cancelling };
    // A queued job becomes cancelled at once (finished_at set); a running one is marked for
    // cancelling (its node sees it at its next cancelRequested) and wakes the nodes.
    virtual CancelOutcome requestCancel(std::int64_t jobId) = 0;

    // The store's end of the job, as JobStore::finish, only if `lease` is still the job's lease
    // and the job still runs; false otherwise (nothing written).
    virtual bool finishLeased(const JobLease& lease, JobState state, const std::string& error,
                              std::uint64_t steps, const std::string* resultBlob) = 0;
    // JobStore::setProgress for the lease holder only.
    virtual void setProgressLeased(const JobLease& lease, double progress) = 0;

    // A held job back to queued at once, without backoff (a node that stops gracefully), or
    // cancelled (finished_at set) when its cancel was asked meanwhile. False if `lease` is not
    // the job's lease or the job does not run.
    virtual bool release(const JobLease& lease) = 0;

    // Running jobs whose lease has expired: cancelled if that was asked, else queued again, available after
    // backoff * 2^(claims - 1) (at most maxBackoff), or dead once claimed maxAttempts times
    // (error: "its node stopped answering N times; last node <id>", finished_at set).
    virtual std::vector<ExpiredLease> expireLeases(int maxAttempts, std::chrono::milliseconds backoff,
                                                   std::chrono::milliseconds maxBackoff) = 0;

    // Jobs of the user in state queued (on every node): the per-user queue limit.
    virtual int queuedCount(std::int64_t ownerId) = 0;
    // Who holds the job's current lease; nullopt when it is not running.
    virtual std::optional<LeaseHolder> holder(std::int64_t jobId) = 0;
    // How many times the job has been claimed (its lease number).
    virtual std::int64_t claims(std::int64_t jobId) = 0;

    // Registers the node or refreshes it (last seen: now).
    virtual void touchNode(const NodeInfo& node) = 0;
    virtual void removeNode(const std::string& nodeId) = 0;
    // Nodes seen within `within`.
    virtual std::vector<NodeInfo> liveNodes(std::chrono::milliseconds within) = 0;

    // Wakes waitForWork in every node (PostgreSQL: NOTIFY tlmhub_jobs; SQLite: this process
    // only, other processes poll). Called after create and requestCancel.
    virtual void notifyWork() = 0;
    // Waits until notifyWork or `timeout`; true if woken. PostgreSQL: LISTEN on a connection
    // of its own, opened on first call and reopened after a lost connection.
    virtual bool waitForWork(std::chrono::milliseconds timeout) = 0;
    // Ends a waitForWork in progress in this process (shutdown), or the next one if none is in
    // progress, so that a wait beginning just after it does not hold shutdown up either.
    virtual void interruptWait() = 0;
};

// For both back ends' expireLeases: how long a job claimed `claims` times waits before it
// may be claimed again (backoff * 2^(claims - 1), at most maxBackoff), and the error of a job
// that is dead.
std::chrono::milliseconds leaseBackoff(std::int64_t claims, std::chrono::milliseconds backoff,
                                       std::chrono::milliseconds maxBackoff);
std::string deadLeaseError(std::int64_t claims, const std::string& lastNode);

} // namespace tlmhub::server
