// JobLeaseStore's contract (server/store/JobLeaseStore.h) on both back ends: fair claims with a
// per-user limit that holds across nodes and threads, leases that are renewed, expire, back
// off and end dead, fencing by the lease number, cancelling, nodes and wake-ups.
#include "StoreBackends.h"

#include "server/store/UnixTime.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <thread>

using namespace tlmhub::server;
using namespace std::chrono_literals;

namespace tlmhub::test {
namespace {

class JobLeaseStoreConformance : public StoreTest {
protected:
    JobLeaseStore& leases() { return store().jobLeases(); }

    std::vector<JobLease> claim(const std::string& node, std::size_t count, int maxRunningPerUser = 2,
                                std::chrono::milliseconds leaseTime = 60s, bool idleOwnersOnly = false)
    {
        ClaimRequest request;
        request.nodeId = node;
        request.count = count;
        request.maxRunningPerUser = maxRunningPerUser;
        request.leaseTime = leaseTime;
        request.idleOwnersOnly = idleOwnersOnly;
        return leases().claim(request);
    }

    // A job claimed by `node` whose lease has expired by the time this returns.
    JobLease claimAndLetExpire(const std::string& node)
    {
        const auto claimed = claim(node, 1, 2, 1ms);
        if (claimed.size() != 1) throw std::runtime_error("nothing to claim");
        std::this_thread::sleep_for(20ms);
        return claimed[0];
    }

    JobState stateOf(std::int64_t id) { return store().jobs().info(id)->state; }
};
TLMHUB_STORE_CONFORMANCE(JobLeaseStoreConformance);

std::vector<std::int64_t> idsOf(const std::vector<JobLease>& claimed)
{
    std::vector<std::int64_t> ids;
    for (const auto& lease : claimed) ids.push_back(lease.jobId);
    return ids;
}

long long millisNow()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

TEST(JobLeaseBackoff, DoublesWithEveryClaimUpToTheCap)
{
    EXPECT_EQ(leaseBackoff(1, 100ms, 1000ms), 100ms);
    EXPECT_EQ(leaseBackoff(2, 100ms, 1000ms), 200ms);
    EXPECT_EQ(leaseBackoff(3, 100ms, 1000ms), 400ms);
    EXPECT_EQ(leaseBackoff(5, 100ms, 1000ms), 1000ms);
    EXPECT_EQ(leaseBackoff(1'000'000, 100ms, 1000ms), 1000ms);   // no overflow
    EXPECT_EQ(deadLeaseError(3, "node-7"), "its node stopped answering 3 times; last node node-7");
}

TEST_P(JobLeaseStoreConformance, ClaimsGoFairlyBetweenUsersUpToTheirLimit)
{
    // Created all of A's first: in order of id alone A would take every place.
    std::vector<std::int64_t> a, b;
    for (int i = 0; i < 5; ++i) a.push_back(addJob(1));
    for (int i = 0; i < 2; ++i) b.push_back(addJob(2));
    const long long before = unixNow();
    const auto claimed = claim("node-1", 10);
    EXPECT_EQ(idsOf(claimed), (std::vector<std::int64_t>{a[0], b[0], a[1], b[1]}));
    for (const auto& lease : claimed) {
        EXPECT_EQ(lease.lease, 1);
        EXPECT_EQ(lease.ownerId, std::count(a.begin(), a.end(), lease.jobId) ? 1 : 2);
        const auto info = store().jobs().info(lease.jobId);
        EXPECT_EQ(info->state, JobState::Running);
        EXPECT_GE(info->startedAt, before - 1);
        EXPECT_EQ(info->progress, 0.0);
    }
    EXPECT_TRUE(claim("node-1", 10).empty()) << "both users are at their limit";
    EXPECT_EQ(leases().queuedCount(1), 3);

    // One of A's ends: A's next (oldest) job may start, and only that one.
    ASSERT_TRUE(leases().finishLeased(claimed[0], JobState::Done, "", 10, nullptr));
    EXPECT_EQ(idsOf(claim("node-1", 10)), (std::vector<std::int64_t>{a[2]}));
    EXPECT_TRUE(claim("node-1", 10).empty());
}

TEST_P(JobLeaseStoreConformance, TheCountLimitsAClaimAndTheNextOneGoesOn)
{
    std::vector<std::int64_t> a, b;
    for (int i = 0; i < 3; ++i) a.push_back(addJob(1));
    for (int i = 0; i < 3; ++i) b.push_back(addJob(2));
    EXPECT_EQ(idsOf(claim("node-1", 3, 3)), (std::vector<std::int64_t>{a[0], b[0], a[1]}));
    EXPECT_EQ(idsOf(claim("node-1", 3, 3)), (std::vector<std::int64_t>{b[1], a[2], b[2]}));
}

TEST_P(JobLeaseStoreConformance, IdleOwnersOnlyTakesTheOldestJobOfUsersWithNothingRunning)
{
    const std::int64_t a0 = addJob(1);
    addJob(1);
    ASSERT_EQ(idsOf(claim("node-1", 1)), (std::vector<std::int64_t>{a0}));
    const std::int64_t b0 = addJob(2);
    addJob(2);
    const std::int64_t c0 = addJob(3);
    EXPECT_EQ(idsOf(claim("node-1", 5, 2, 60s, true)), (std::vector<std::int64_t>{b0, c0}));
    EXPECT_TRUE(claim("node-1", 5, 2, 60s, true).empty()) << "everyone has a job running now";
    EXPECT_EQ(claim("node-1", 5).size(), 2u) << "A's and B's second jobs, without the restriction";
}

TEST_P(JobLeaseStoreConformance, TheLimitHoldsForNodesClaimingInTurn)
{
    std::vector<std::int64_t> a;
    for (int i = 0; i < 4; ++i) a.push_back(addJob(1));
    const auto first = claim("node-1", 1);
    const auto second = claim("node-2", 1);
    EXPECT_EQ(idsOf(first), (std::vector<std::int64_t>{a[0]}));
    EXPECT_EQ(idsOf(second), (std::vector<std::int64_t>{a[1]}));
    EXPECT_TRUE(claim("node-1", 1).empty());
    EXPECT_TRUE(claim("node-2", 1).empty());
    EXPECT_EQ(leases().holder(a[0])->nodeId, "node-1");
    EXPECT_EQ(leases().holder(a[1])->nodeId, "node-2");
    ASSERT_TRUE(leases().finishLeased(second[0], JobState::Failed, "boom", 0, nullptr));
    EXPECT_EQ(idsOf(claim("node-1", 2)), (std::vector<std::int64_t>{a[2]}));
    EXPECT_TRUE(claim("node-2", 1).empty());
}

TEST_P(JobLeaseStoreConformance, ConcurrentClaimsTakeEveryJobOnceAndNoUserPassesTheLimit)
{
    constexpr int kUsers = 5;
    constexpr int kJobs = 30;
    constexpr int kLimit = 2;
    for (int i = 0; i < kJobs; ++i) addJob(1 + i % kUsers);
    std::mutex mutex;
    std::vector<std::int64_t> claimedIds;
    std::atomic<int> finished = 0;
    std::atomic<int> holding[kUsers + 1] = {};
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    runAtOnce(8, [&](int thread) {
        const std::string node = "node-" + std::to_string(thread);
        while (finished.load() < kJobs && std::chrono::steady_clock::now() < deadline) {
            const auto claimed = claim(node, 1 + static_cast<std::size_t>(thread % 3), kLimit);
            if (claimed.empty()) {
                std::this_thread::sleep_for(1ms);
                continue;
            }
            for (const auto& lease : claimed) {
                EXPECT_LE(holding[lease.ownerId].fetch_add(1) + 1, kLimit) << "user " << lease.ownerId;
                std::lock_guard lock(mutex);
                claimedIds.push_back(lease.jobId);
            }
            // What the database says at one moment: no user above the limit.
            std::map<std::int64_t, int> running;
            for (const auto& job : store().jobs().listInState(JobState::Running)) ++running[job.ownerId];
            for (const auto& [owner, n] : running) EXPECT_LE(n, kLimit) << "user " << owner;
            for (const auto& lease : claimed) {
                holding[lease.ownerId].fetch_sub(1);
                EXPECT_TRUE(leases().finishLeased(lease, JobState::Done, "", 1, nullptr)) << lease.jobId;
                finished.fetch_add(1);
            }
        }
    });
    EXPECT_EQ(finished.load(), kJobs);
    std::sort(claimedIds.begin(), claimedIds.end());
    EXPECT_EQ(std::adjacent_find(claimedIds.begin(), claimedIds.end()), claimedIds.end()) << "a job claimed twice";
    EXPECT_EQ(claimedIds.size(), static_cast<std::size_t>(kJobs));
    EXPECT_EQ(store().jobs().listInState(JobState::Done).size(), static_cast<std::size_t>(kJobs));
    for (const auto id : claimedIds) EXPECT_EQ(leases().claims(id), 1);
}

TEST_P(JobLeaseStoreConformance, RenewExtendsHeldLeasesAndNamesTheLostOnes)
{
    const std::int64_t x = addJob(1);
    const std::int64_t y = addJob(2);
    const auto claimed = claim("node-1", 2, 2, 1ms);
    ASSERT_EQ(claimed.size(), 2u);
    EXPECT_TRUE(leases().renew("node-1", claimed, 60s).empty());
    std::this_thread::sleep_for(20ms);
    EXPECT_TRUE(leases().expireLeases(5, 0ms, 0ms).empty()) << "renewed past the 1 ms of the claim";

    EXPECT_EQ(leases().renew("node-2", claimed, 60s), (std::vector<std::int64_t>{x, y})) << "another node's";
    JobLease stale = claimed[1];
    stale.lease += 1;
    EXPECT_EQ(leases().renew("node-1", {claimed[0], stale}, 60s), (std::vector<std::int64_t>{y}));
    ASSERT_TRUE(leases().finishLeased(claimed[0], JobState::Done, "", 1, nullptr));
    EXPECT_EQ(leases().renew("node-1", claimed, 60s), (std::vector<std::int64_t>{x})) << "finished";
    EXPECT_TRUE(leases().renew("node-1", {}, 60s).empty());
}

TEST_P(JobLeaseStoreConformance, OnlyTheCurrentLeaseStoresTheEnd)
{
    const std::int64_t id = addJob(1);
    const JobLease first = claimAndLetExpire("node-1");
    EXPECT_EQ(first.lease, 1);
    const auto expired = leases().expireLeases(5, 0ms, 0ms);
    ASSERT_EQ(expired.size(), 1u);
    EXPECT_EQ(expired[0].jobId, id);
    EXPECT_EQ(expired[0].state, JobState::Queued);
    EXPECT_EQ(stateOf(id), JobState::Queued);
    const auto second = claim("node-2", 1);
    ASSERT_EQ(second.size(), 1u);
    EXPECT_EQ(second[0].lease, 2);
    EXPECT_EQ(leases().claims(id), 2);

    // The paused node wakes up and tries to store its end: refused, nothing written.
    const std::string stale = "result of the first run";
    leases().setProgressLeased(first, 0.7);
    EXPECT_FALSE(leases().finishLeased(first, JobState::Done, "", 100, &stale));
    EXPECT_FALSE(leases().release(first));
    auto info = store().jobs().info(id);
    EXPECT_EQ(info->state, JobState::Running);
    EXPECT_EQ(info->progress, 0.0);
    EXPECT_FALSE(store().results().has(id));

    const std::string blob("result\0of the second", 20);
    leases().setProgressLeased(second[0], 0.5);
    EXPECT_EQ(store().jobs().info(id)->progress, 0.5);
    EXPECT_TRUE(leases().finishLeased(second[0], JobState::Done, "", 100, &blob));
    EXPECT_FALSE(leases().finishLeased(second[0], JobState::Failed, "again", 1, &stale)) << "finished already";
    info = store().jobs().info(id);
    EXPECT_EQ(info->state, JobState::Done);
    EXPECT_EQ(info->progress, 1.0);
    EXPECT_EQ(info->steps, 100u);
    EXPECT_EQ(info->error, "");
    EXPECT_GT(info->finishedAt, 0);
    EXPECT_EQ(store().results().blob(id), std::optional<std::string>(blob));
    EXPECT_FALSE(leases().holder(id));
}

TEST_P(JobLeaseStoreConformance, AnExpiredJobWaitsItsBackoffAndDiesAfterMaxAttempts)
{
    const std::int64_t id = addJob(1);
    claimAndLetExpire("node-1");
    const auto expired = leases().expireLeases(2, 400ms, 10s);
    ASSERT_EQ(expired.size(), 1u);
    EXPECT_EQ(expired[0].state, JobState::Queued);
    EXPECT_EQ(stateOf(id), JobState::Queued);
    EXPECT_EQ(leases().queuedCount(1), 1);
    EXPECT_FALSE(leases().holder(id));
    EXPECT_TRUE(claim("node-2", 1).empty()) << "within its backoff";
    std::this_thread::sleep_for(500ms);
    EXPECT_TRUE(leases().expireLeases(2, 400ms, 10s).empty()) << "a queued job does not expire";

    const JobLease second = claimAndLetExpire("node-2");
    EXPECT_EQ(second.jobId, id);
    EXPECT_EQ(second.lease, 2);
    const auto died = leases().expireLeases(2, 400ms, 10s);
    ASSERT_EQ(died.size(), 1u);
    EXPECT_EQ(died[0].state, JobState::Dead);
    const auto info = store().jobs().info(id);
    EXPECT_EQ(info->state, JobState::Dead);
    EXPECT_EQ(info->error, "its node stopped answering 2 times; last node node-2");
    EXPECT_GT(info->finishedAt, 0);
    EXPECT_FALSE(leases().holder(id));
    EXPECT_TRUE(claim("node-3", 1).empty());
    EXPECT_FALSE(leases().finishLeased(second, JobState::Done, "", 1, nullptr));
    EXPECT_EQ(leases().requestCancel(id), JobLeaseStore::CancelOutcome::NotActive);
}

TEST_P(JobLeaseStoreConformance, ALeaseStillInTimeDoesNotExpire)
{
    addJob(1);
    ASSERT_EQ(claim("node-1", 1, 2, 60s).size(), 1u);
    EXPECT_TRUE(leases().expireLeases(1, 0ms, 0ms).empty());
}

TEST_P(JobLeaseStoreConformance, AnExpiredJobWhoseCancellationWasAskedIsCancelledNotQueued)
{
    const std::int64_t id = addJob(1);
    ASSERT_EQ(claim("node-1", 1, 2, 1ms).size(), 1u);
    EXPECT_EQ(leases().requestCancel(id), JobLeaseStore::CancelOutcome::Cancelling);
    std::this_thread::sleep_for(20ms);   // its node died before it saw the request
    const auto expired = leases().expireLeases(3, 0ms, 0ms);
    ASSERT_EQ(expired.size(), 1u);
    EXPECT_EQ(expired[0].state, JobState::Cancelled);
    EXPECT_EQ(stateOf(id), JobState::Cancelled);
    EXPECT_GT(store().jobs().info(id)->finishedAt, 0);
    EXPECT_TRUE(claim("node-2", 1).empty());
}

TEST_P(JobLeaseStoreConformance, CancellingAQueuedJobEndsItAndARunningOneAsksItsNode)
{
    const std::int64_t queued = addJob(1);
    const std::int64_t running = addJob(2);
    const std::int64_t other = addJob(3);
    ASSERT_TRUE(store().jobs().markRunning(other));   // not claimed: no lease
    // Claim only B's job: cancel A's first, while queued.
    EXPECT_EQ(leases().requestCancel(queued), JobLeaseStore::CancelOutcome::Cancelled);
    auto info = store().jobs().info(queued);
    EXPECT_EQ(info->state, JobState::Cancelled);
    EXPECT_GT(info->finishedAt, 0);
    EXPECT_EQ(leases().requestCancel(queued), JobLeaseStore::CancelOutcome::NotActive) << "finished";

    const auto claimed = claim("node-1", 1);
    ASSERT_EQ(idsOf(claimed), (std::vector<std::int64_t>{running}));
    EXPECT_TRUE(leases().cancelRequested({running, other}).empty());
    EXPECT_EQ(leases().requestCancel(running), JobLeaseStore::CancelOutcome::Cancelling);
    EXPECT_EQ(stateOf(running), JobState::Running) << "its node ends it";
    EXPECT_EQ(leases().cancelRequested({running, other, queued}), (std::vector<std::int64_t>{running}));
    EXPECT_TRUE(leases().cancelRequested({}).empty());
    EXPECT_EQ(leases().requestCancel(running + 1000), JobLeaseStore::CancelOutcome::NotActive);

    // Its node stops gracefully before it saw the request: the job ends cancelled rather
    // than going back to the queue to run again.
    const long long before = unixNow();
    ASSERT_TRUE(leases().release(claimed[0]));
    EXPECT_EQ(stateOf(running), JobState::Cancelled);
    EXPECT_GE(store().jobs().info(running)->finishedAt, before);
    EXPECT_FALSE(leases().holder(running));
    EXPECT_TRUE(claim("node-2", 1).empty()) << "nothing left to claim";
    EXPECT_TRUE(leases().cancelRequested({running}).empty()) << "no longer running";
}

TEST_P(JobLeaseStoreConformance, ReleasePutsAHeldJobBackAtOnce)
{
    const std::int64_t id = addJob(1);
    const auto claimed = claim("node-1", 1, 2, 60s);
    ASSERT_EQ(claimed.size(), 1u);
    JobLease wrong = claimed[0];
    wrong.lease = 7;
    EXPECT_FALSE(leases().release(wrong));
    EXPECT_EQ(stateOf(id), JobState::Running);
    EXPECT_TRUE(leases().release(claimed[0]));
    EXPECT_FALSE(leases().release(claimed[0])) << "no longer held";
    EXPECT_EQ(stateOf(id), JobState::Queued);
    EXPECT_FALSE(leases().holder(id));
    EXPECT_EQ(leases().queuedCount(1), 1);
    const auto again = claim("node-2", 1);
    ASSERT_EQ(again.size(), 1u) << "no backoff after a release";
    EXPECT_EQ(again[0].lease, 2);
}

TEST_P(JobLeaseStoreConformance, QueuedCountCountsTheUsersQueuedJobsOnly)
{
    EXPECT_EQ(leases().queuedCount(1), 0);
    addJob(1);
    addJob(1);
    const std::int64_t third = addJob(1);
    addJob(2);
    EXPECT_EQ(leases().queuedCount(1), 3);
    EXPECT_EQ(leases().queuedCount(2), 1);
    ASSERT_EQ(claim("node-1", 5, 1).size(), 2u);   // one of each user
    EXPECT_EQ(leases().queuedCount(1), 2);
    EXPECT_EQ(leases().requestCancel(third), JobLeaseStore::CancelOutcome::Cancelled);
    EXPECT_EQ(leases().queuedCount(1), 1);
    EXPECT_EQ(leases().queuedCount(2), 0);
}

TEST_P(JobLeaseStoreConformance, TheHolderIsTheNodeWithItsRegisteredAddress)
{
    const std::int64_t id = addJob(1);
    const std::int64_t waiting = addJob(1);
    EXPECT_FALSE(leases().holder(id));
    ASSERT_EQ(claim("node-1", 1).size(), 1u);
    auto holder = leases().holder(id);
    ASSERT_TRUE(holder);
    EXPECT_EQ(holder->nodeId, "node-1");
    EXPECT_EQ(holder->address, "") << "not registered";
    EXPECT_EQ(holder->lease, 1);
    leases().touchNode(NodeInfo{"node-1", "worker", "http://10.0.0.5:8080", 0});
    holder = leases().holder(id);
    ASSERT_TRUE(holder);
    EXPECT_EQ(holder->address, "http://10.0.0.5:8080");
    EXPECT_FALSE(leases().holder(waiting)) << "queued";
    EXPECT_FALSE(leases().holder(id + 1000));
    EXPECT_EQ(leases().claims(waiting), 0);
    EXPECT_EQ(leases().claims(id + 1000), 0);
}

TEST_P(JobLeaseStoreConformance, NodesAreLiveWhileTheyTouchAndGoWhenRemoved)
{
    EXPECT_TRUE(leases().liveNodes(60s).empty());
    const long long before = millisNow();
    leases().touchNode(NodeInfo{"api-1", "api", "http://a:1", 0});
    leases().touchNode(NodeInfo{"worker-1", "worker", "", 0});
    leases().touchNode(NodeInfo{"api-1", "all", "http://a:2", 0});   // refreshed, not added
    auto nodes = leases().liveNodes(60s);
    ASSERT_EQ(nodes.size(), 2u);
    std::sort(nodes.begin(), nodes.end(), [](const NodeInfo& l, const NodeInfo& r) { return l.id < r.id; });
    EXPECT_EQ(nodes[0].id, "api-1");
    EXPECT_EQ(nodes[0].role, "all");
    EXPECT_EQ(nodes[0].address, "http://a:2");
    EXPECT_EQ(nodes[1].id, "worker-1");
    EXPECT_EQ(nodes[1].role, "worker");
    EXPECT_EQ(nodes[1].address, "");
    // PostgreSQL's clock is the database's: the same machine here, so within a few seconds.
    EXPECT_GT(nodes[0].lastSeenMillis, before - 5000);
    EXPECT_LT(nodes[0].lastSeenMillis, millisNow() + 5000);

    std::this_thread::sleep_for(50ms);
    leases().touchNode(NodeInfo{"worker-1", "worker", "", 0});
    nodes = leases().liveNodes(30ms);
    ASSERT_EQ(nodes.size(), 1u) << "api-1 was last seen too long ago";
    EXPECT_EQ(nodes[0].id, "worker-1");

    leases().removeNode("worker-1");
    leases().removeNode("never-there");
    nodes = leases().liveNodes(60s);
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_EQ(nodes[0].id, "api-1");
}

// Runs waitForWork(10 s) on a thread of its own; `then` runs once it waits (about).
struct Waiter {
    std::thread thread;
    std::atomic<bool> done = false;
    bool woken = false;
    std::chrono::steady_clock::duration took{};

    explicit Waiter(JobLeaseStore& store)
    {
        thread = std::thread([this, &store] {
            const auto start = std::chrono::steady_clock::now();
            woken = store.waitForWork(10s);
            took = std::chrono::steady_clock::now() - start;
            done = true;
        });
        std::this_thread::sleep_for(200ms);   // in its wait by now
    }
    void join() { thread.join(); }
};

TEST_P(JobLeaseStoreConformance, AWaitEndsAtItsTimeoutWithoutWork)
{
    const auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(leases().waitForWork(150ms));
    const auto took = std::chrono::steady_clock::now() - start;
    EXPECT_GE(took, 140ms);
    EXPECT_LT(took, 5s);
}

TEST_P(JobLeaseStoreConformance, NotifyWorkWakesAWaiterInThisProcess)
{
    Waiter waiter(leases());
    EXPECT_FALSE(waiter.done.load()) << "woke without a notification";
    leases().notifyWork();
    waiter.join();
    EXPECT_TRUE(waiter.woken);
    EXPECT_LT(waiter.took, 5s);
    EXPECT_FALSE(leases().waitForWork(50ms)) << "the notification was used up";
}

TEST_P(JobLeaseStoreConformance, ANotificationBetweenWaitsIsNotLost)
{
    leases().notifyWork();
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(leases().waitForWork(10s));
    EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST_P(JobLeaseStoreConformance, CancellingARunningJobWakesTheWaiters)
{
    const std::int64_t id = addJob(1);
    ASSERT_EQ(claim("node-1", 1).size(), 1u);
    Waiter waiter(leases());
    EXPECT_EQ(leases().requestCancel(id), JobLeaseStore::CancelOutcome::Cancelling);
    waiter.join();
    EXPECT_TRUE(waiter.woken);
    EXPECT_LT(waiter.took, 5s);
}

TEST_P(JobLeaseStoreConformance, InterruptWaitEndsAWait)
{
    Waiter waiter(leases());
    leases().interruptWait();
    waiter.join();
    EXPECT_FALSE(waiter.woken);
    EXPECT_LT(waiter.took, 5s);
    // An interruption before a wait ends that wait at once (shutdown racing a wait that is
    // about to begin), and only that one: a queue started again waits as before.
    leases().interruptWait();
    auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(leases().waitForWork(10s));
    EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
    start = std::chrono::steady_clock::now();
    EXPECT_FALSE(leases().waitForWork(200ms));
    EXPECT_GE(std::chrono::steady_clock::now() - start, 150ms);
}

TEST_P(JobLeaseStoreConformance, NotifyWorkWakesAnotherNodeOnTheSameDatabase)
{
    if (GetParam() == Backend::SQLite) GTEST_SKIP() << "SQLite wakes this process only (other processes poll)";
    const auto other = db->open();
    JobLeaseStore& theirs = other->jobLeases();
    EXPECT_FALSE(theirs.waitForWork(20ms)) << "(opens its LISTEN connection)";
    EXPECT_FALSE(leases().waitForWork(20ms)) << "(and this one's)";
    Waiter waiter(theirs);
    EXPECT_FALSE(waiter.done.load()) << "woke without a notification";
    leases().notifyWork();
    waiter.join();
    EXPECT_TRUE(waiter.woken);
    EXPECT_LT(waiter.took, 5s);
    // Its own notification does not wake this node a second time through the database.
    EXPECT_TRUE(leases().waitForWork(10ms)) << "woken in process";
    EXPECT_FALSE(leases().waitForWork(300ms)) << "and not again by its own NOTIFY";
}

TEST_P(JobLeaseStoreConformance, ADeadJobIsRemovedWithTheFinishedOnes)
{
    const std::int64_t id = addJob(1);
    claimAndLetExpire("node-1");
    const auto expired = leases().expireLeases(1, 0ms, 0ms);
    ASSERT_EQ(expired.size(), 1u);
    ASSERT_EQ(expired[0].state, JobState::Dead);
    const std::int64_t queued = addJob(1);
    waitForNextSecond();
    EXPECT_EQ(store().jobs().removeFinishedBefore(unixNow() + 1), 1);
    EXPECT_FALSE(store().jobs().info(id));
    EXPECT_TRUE(store().jobs().info(queued));
}

} // namespace
} // namespace tlmhub::test
