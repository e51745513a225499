#pragma once
// How one server process takes part in the job queue that the database holds for all nodes
// (JobLeaseStore.h, docs/scale-out.md): whether it runs jobs, how long its leases last, and
// how many jobs it holds at once.
#include <chrono>
#include <cstddef>
#include <string>

namespace tlmhub::server {

struct QueueNode {
    std::string id = "local";   // unique per process start in a deployment of several nodes
    std::string role = "all";   // as registered in the nodes table
    std::string address;        // where other nodes reach this one ("" on a single node)
    bool runsJobs = true;       // role worker or all; an API node only queues
    // Role worker: a node that stops gracefully puts its started jobs back in the queue for
    // other workers. Role all (one node): they end interrupted, as they always have.
    bool releaseOnShutdown = false;
    std::chrono::milliseconds leaseTime{10'000};   // renewed every leaseTime / 3
    int maxAttempts = 3;                           // claims before a job is dead
    std::chrono::milliseconds backoff{1'000}, maxBackoff{60'000};
    // Expired leases are looked for, and the queue polled (NOTIFY is only a hint), this often.
    std::chrono::milliseconds pollPeriod{500};
    // Jobs the node holds at most (queued here or started): any user's...
    std::size_t heldLimit = 64;
    // ...and jobs of users with nothing running anywhere (their first slice: JobQueue.h).
    std::size_t firstSliceHeldLimit = 64;
};

} // namespace tlmhub::server
