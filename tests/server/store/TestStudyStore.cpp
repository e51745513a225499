// StudyStore's contract (server/store/StudyStore.h) on both back ends.
#include "StoreBackends.h"

#include "server/store/UnixTime.h"

#include <atomic>
#include <chrono>
#include <thread>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

// The node the tests' studies are held by, and a limit of active studies no test reaches
// unless it means to.
const std::string kNode = "node-a";
constexpr int kNoLimit = 1000;

class StudyStoreConformance : public StoreTest {
protected:
    std::int64_t addStudy(std::int64_t ownerId, std::int64_t runsTotal = 10, const std::string& node = kNode)
    {
        const auto id = store().studies().create(ownerId, std::nullopt, "sweep", "study", "{}", runsTotal, node, kNoLimit);
        if (!id) throw std::runtime_error("cannot add a study of " + std::to_string(ownerId));
        return *id;
    }
    std::int64_t addRunningStudy(std::int64_t ownerId)
    {
        const std::int64_t id = addStudy(ownerId);
        if (!store().studies().markRunning(id, kNode)) throw std::runtime_error("cannot start study " + std::to_string(id));
        return id;
    }
};
TLMHUB_STORE_CONFORMANCE(StudyStoreConformance);

StudyRun okRun(std::int64_t index)
{
    return StudyRun{index, true, R"({"Pump.Dp":)" + std::to_string(index) + "}", R"({"Mass#P1#x:final":0.5})", "", false, ""};
}

StudyRun failedRun(std::int64_t index)
{
    return StudyRun{index, false, R"({"Pump.Dp":-1})", "{}", "the model diverged", false, ""};
}

std::vector<std::int64_t> idsOf(const std::vector<StudyInfo>& studies)
{
    std::vector<std::int64_t> ids;
    for (const auto& s : studies) ids.push_back(s.id);
    return ids;
}

std::vector<std::int64_t> indexesOf(const std::vector<StudyRun>& runs)
{
    std::vector<std::int64_t> indexes;
    for (const auto& r : runs) indexes.push_back(r.index);
    return indexes;
}

TEST_P(StudyStoreConformance, CreateStoresAQueuedStudyAndItsRequest)
{
    const User alice = addUser("alice");
    const std::string request = R"({"kind":"sweep","name":"pump size","sweep":{"parameters":{"Pump.Dp":[1e-5,2e-5]}}})";
    const long long before = unixNow();
    const auto id = store().studies().create(alice.id, 42, "sweep", "pump size \xc3\xa5", request, 12, kNode, kNoLimit);
    const long long after = unixNow();
    ASSERT_TRUE(id);
    const auto info = store().studies().info(*id);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->id, *id);
    EXPECT_EQ(info->ownerId, alice.id);
    EXPECT_EQ(info->modelId, 42);
    EXPECT_EQ(info->kind, "sweep");
    EXPECT_EQ(info->name, "pump size \xc3\xa5");
    EXPECT_EQ(info->state, JobState::Queued);
    EXPECT_EQ(info->runsTotal, 12);
    EXPECT_EQ(info->runsDone, 0);
    EXPECT_EQ(info->runsFailed, 0);
    EXPECT_EQ(info->error, "");
    EXPECT_GE(info->createdAt, before);
    EXPECT_LE(info->createdAt, after);
    EXPECT_EQ(info->startedAt, 0);
    EXPECT_EQ(info->finishedAt, 0);
    EXPECT_EQ(info->summary, "");
    EXPECT_EQ(store().studies().request(*id), request);
    EXPECT_FALSE(store().studies().info(*id + 1000));
    EXPECT_FALSE(store().studies().request(*id + 1000));
}

TEST_P(StudyStoreConformance, AStudyOfModelTextHasNoModelId)
{
    const User alice = addUser("alice");
    const auto id = store().studies().create(alice.id, std::nullopt, "optimise", "pid", "{}", 200, kNode, kNoLimit);
    ASSERT_TRUE(id);
    EXPECT_EQ(store().studies().info(*id)->modelId, std::nullopt);
}

TEST_P(StudyStoreConformance, CreateForAMissingOwnerIsRefused)
{
    EXPECT_EQ(store().studies().create(4242, std::nullopt, "sweep", "orphan", "{}", 1, kNode, kNoLimit), std::nullopt);
    EXPECT_TRUE(store().studies().listForOwner(4242).empty());
}

TEST_P(StudyStoreConformance, ListForOwnerIsTheOwnersNewestFirst)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    const auto a1 = addStudy(alice.id);
    const auto b1 = addStudy(bob.id);
    const auto a2 = addStudy(alice.id);
    EXPECT_EQ(idsOf(store().studies().listForOwner(alice.id)), (std::vector<std::int64_t>{a2, a1}));
    EXPECT_EQ(idsOf(store().studies().listForOwner(bob.id)), (std::vector<std::int64_t>{b1}));
}

TEST_P(StudyStoreConformance, ListInStateIsOldestFirst)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    const auto s1 = addStudy(alice.id);
    const auto s2 = addStudy(bob.id);
    const auto s3 = addStudy(alice.id);
    const auto s4 = addStudy(bob.id);
    ASSERT_TRUE(store().studies().markRunning(s3, kNode));
    ASSERT_TRUE(store().studies().markRunning(s1, kNode));
    EXPECT_EQ(idsOf(store().studies().listInState(JobState::Running)), (std::vector<std::int64_t>{s1, s3}));
    EXPECT_EQ(idsOf(store().studies().listInState(JobState::Queued)), (std::vector<std::int64_t>{s2, s4}));
    EXPECT_TRUE(store().studies().listInState(JobState::Done).empty());
}

TEST_P(StudyStoreConformance, MarkRunningStartsOnlyAQueuedStudy)
{
    const User alice = addUser("alice");
    const auto id = addStudy(alice.id);
    const long long before = unixNow();
    EXPECT_TRUE(store().studies().markRunning(id, kNode));
    const auto info = store().studies().info(id);
    EXPECT_EQ(info->state, JobState::Running);
    EXPECT_GE(info->startedAt, before);
    EXPECT_FALSE(store().studies().markRunning(id, kNode)) << "running already";
    EXPECT_FALSE(store().studies().markRunning(id + 1000, kNode));
    ASSERT_TRUE(store().studies().finish(id, JobState::Done, "", "{}"));
    EXPECT_FALSE(store().studies().markRunning(id, kNode)) << "finished";
}

TEST_P(StudyStoreConformance, AddRunStoresTheRunAndCountsItDoneOrFailed)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    EXPECT_TRUE(store().studies().addRun(id, okRun(0), nullptr));
    EXPECT_TRUE(store().studies().addRun(id, failedRun(1), nullptr));
    EXPECT_TRUE(store().studies().addRun(id, okRun(2), nullptr));
    const auto info = store().studies().info(id);
    EXPECT_EQ(info->runsDone, 2);
    EXPECT_EQ(info->runsFailed, 1);
    const auto runs = store().studies().runs(id, 0, 100);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_EQ(runs[0].index, 0);
    EXPECT_TRUE(runs[0].ok);
    EXPECT_EQ(runs[0].parameters, okRun(0).parameters);
    EXPECT_EQ(runs[0].outputs, okRun(0).outputs);
    EXPECT_EQ(runs[0].error, "");
    EXPECT_FALSE(runs[0].hasResult);
    EXPECT_EQ(runs[1].index, 1);
    EXPECT_FALSE(runs[1].ok);
    EXPECT_EQ(runs[1].parameters, failedRun(1).parameters);
    EXPECT_EQ(runs[1].outputs, "{}");
    EXPECT_EQ(runs[1].error, "the model diverged");
}

TEST_P(StudyStoreConformance, AddRunIsRefusedUnlessTheStudyRuns)
{
    const User alice = addUser("alice");
    const auto queued = addStudy(alice.id);
    EXPECT_FALSE(store().studies().addRun(queued, okRun(0), nullptr)) << "queued";
    const auto finished = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().finish(finished, JobState::Cancelled, "", "{}"));
    EXPECT_FALSE(store().studies().addRun(finished, okRun(0), nullptr)) << "cancelled";
    EXPECT_FALSE(store().studies().addRun(finished + 1000, okRun(0), nullptr)) << "no such study";
    const std::string blob = "a result";
    EXPECT_FALSE(store().studies().addRun(queued, okRun(1), &blob));
    for (const auto id : {queued, finished}) {
        EXPECT_TRUE(store().studies().runs(id, 0, 100).empty());
        EXPECT_EQ(store().studies().info(id)->runsDone, 0);
        EXPECT_EQ(store().studies().info(id)->runsFailed, 0);
    }
    EXPECT_EQ(store().studies().storedBytes(alice.id), 0u);
}

TEST_P(StudyStoreConformance, AddRunRefusesATakenIndexAndCountsNothing)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().addRun(id, okRun(0), nullptr));
    const std::string blob = "would be a result";
    EXPECT_FALSE(store().studies().addRun(id, failedRun(0), &blob));
    const auto info = store().studies().info(id);
    EXPECT_EQ(info->runsDone, 1);
    EXPECT_EQ(info->runsFailed, 0) << "a refused run was counted";
    const auto runs = store().studies().runs(id, 0, 100);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_TRUE(runs[0].ok) << "the first run was replaced";
    EXPECT_FALSE(store().studies().runResult(id, 0));
    EXPECT_EQ(store().studies().storedBytes(alice.id), 0u);
}

TEST_P(StudyStoreConformance, RunsAddedAtOnceAreEachStoredAndCountedOnce)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    // Four workers race to add the same twenty runs: each index goes in once, counted once.
    constexpr int kRuns = 20;
    std::atomic<int> added = 0;
    runAtOnce(4, [&](int) {
        for (int index = 0; index < kRuns; ++index)
            if (store().studies().addRun(id, okRun(index), nullptr)) added.fetch_add(1);
    });
    EXPECT_EQ(added.load(), kRuns);
    EXPECT_EQ(store().studies().info(id)->runsDone, kRuns);
    EXPECT_EQ(store().studies().runs(id, 0, 100).size(), static_cast<std::size_t>(kRuns));
}

TEST_P(StudyStoreConformance, RunsComeInIndexOrderFromAnIndexUpToALimit)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    const auto other = addRunningStudy(alice.id);
    for (const std::int64_t index : {3, 0, 4, 1, 2}) ASSERT_TRUE(store().studies().addRun(id, okRun(index), nullptr));
    ASSERT_TRUE(store().studies().addRun(other, okRun(7), nullptr));
    EXPECT_EQ(indexesOf(store().studies().runs(id, 0, 100)), (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(indexesOf(store().studies().runs(id, 1, 2)), (std::vector<std::int64_t>{1, 2}));
    EXPECT_EQ(indexesOf(store().studies().runs(id, 3, 100)), (std::vector<std::int64_t>{3, 4}));
    EXPECT_TRUE(store().studies().runs(id, 5, 100).empty());
    EXPECT_TRUE(store().studies().runs(id, 0, 0).empty());
}

TEST_P(StudyStoreConformance, RunResultsComeBackByteForByteAndCountForTheirOwner)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    const auto id = addRunningStudy(alice.id);
    std::string everyByte;
    for (int b = 0; b < 256; ++b) everyByte.push_back(static_cast<char>(b));
    const std::string large(100'000, 'r');
    ASSERT_TRUE(store().studies().addRun(id, okRun(0), &everyByte));
    ASSERT_TRUE(store().studies().addRun(id, okRun(1), nullptr));
    ASSERT_TRUE(store().studies().addRun(id, okRun(2), &large));
    EXPECT_EQ(store().studies().runResult(id, 0), everyByte);
    EXPECT_EQ(store().studies().runResult(id, 1), std::nullopt) << "a run without a kept result";
    EXPECT_EQ(store().studies().runResult(id, 2), large);
    EXPECT_EQ(store().studies().runResult(id, 3), std::nullopt);
    const auto runs = store().studies().runs(id, 0, 100);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_TRUE(runs[0].hasResult);
    EXPECT_FALSE(runs[1].hasResult);
    EXPECT_TRUE(runs[2].hasResult);
    EXPECT_EQ(store().studies().storedBytes(alice.id), everyByte.size() + large.size());
    EXPECT_EQ(store().studies().storedBytes(bob.id), 0u);
    // A job's result is not a study's.
    const std::string jobBlob = "job result";
    addFinishedJob(bob.id, &jobBlob);
    EXPECT_EQ(store().studies().storedBytes(bob.id), 0u);
    // The quota (ResultStore::storedBytes) counts both.
    EXPECT_EQ(store().results().storedBytes(alice.id), everyByte.size() + large.size());
    EXPECT_EQ(store().results().storedBytes(bob.id), jobBlob.size());
}

TEST_P(StudyStoreConformance, SetSummaryReplacesItWhileTheStudyIsNotFinished)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    store().studies().setSummary(id, R"({"best":{"run":0}})");
    EXPECT_EQ(store().studies().info(id)->summary, R"({"best":{"run":0}})");
    store().studies().setSummary(id, R"({"best":{"run":3}})");
    EXPECT_EQ(store().studies().info(id)->summary, R"({"best":{"run":3}})");
    ASSERT_TRUE(store().studies().finish(id, JobState::Done, "", R"({"finish_reason":"converged"})"));
    store().studies().setSummary(id, R"({"best":{"run":9}})");
    EXPECT_EQ(store().studies().info(id)->summary, R"({"finish_reason":"converged"})") << "a late summary overwrote the final one";
}

TEST_P(StudyStoreConformance, FinishSetsTheFinalStateOnce)
{
    const User alice = addUser("alice");
    const auto running = addRunningStudy(alice.id);
    const long long before = unixNow();
    EXPECT_TRUE(store().studies().finish(running, JobState::Failed, "every run failed", R"({"x":1})"));
    auto info = store().studies().info(running);
    EXPECT_EQ(info->state, JobState::Failed);
    EXPECT_EQ(info->error, "every run failed");
    EXPECT_EQ(info->summary, R"({"x":1})");
    EXPECT_GE(info->finishedAt, before);
    EXPECT_FALSE(store().studies().finish(running, JobState::Done, "", "{}")) << "finished already";
    EXPECT_EQ(store().studies().info(running)->state, JobState::Failed);
    // A queued study can be cancelled before it starts.
    const auto queued = addStudy(alice.id);
    EXPECT_TRUE(store().studies().finish(queued, JobState::Cancelled, "", "{}"));
    EXPECT_EQ(store().studies().info(queued)->state, JobState::Cancelled);
    EXPECT_FALSE(store().studies().finish(queued + 1000, JobState::Done, "", "{}"));
}

// Node a answers (a heartbeat in the nodes table); node gone never did: b takes over gone's
// studies only, interrupting the running one and holding the queued one from then on.
TEST_P(StudyStoreConformance, AdoptOrphansTakesOverOnlyTheStudiesOfNodesThatStoppedAnswering)
{
    const User alice = addUser("alice");
    store().jobLeases().touchNode(NodeInfo{kNode, "api", "", 0});
    const auto liveRunning = addRunningStudy(alice.id);
    const auto liveQueued = addStudy(alice.id);
    const auto goneQueued1 = addStudy(alice.id, 10, "node-gone");
    const auto goneRunning = addStudy(alice.id, 10, "node-gone");
    ASSERT_TRUE(store().studies().markRunning(goneRunning, "node-gone"));
    ASSERT_TRUE(store().studies().addRun(goneRunning, okRun(0), nullptr));
    const auto goneQueued2 = addStudy(alice.id, 10, "node-gone");
    const auto goneDone = addStudy(alice.id, 10, "node-gone");
    ASSERT_TRUE(store().studies().finish(goneDone, JobState::Cancelled, "", "{}"));
    const auto own = addStudy(alice.id, 10, "node-b");   // b itself has no heartbeat yet

    const auto adopted = store().studies().adoptOrphans("node-b", std::chrono::seconds(10));
    EXPECT_EQ(idsOf(adopted), (std::vector<std::int64_t>{goneQueued1, goneQueued2})) << "oldest first";
    for (const auto& info : adopted) EXPECT_EQ(info.state, JobState::Queued);
    const auto interrupted = store().studies().info(goneRunning);
    EXPECT_EQ(interrupted->state, JobState::Interrupted);
    EXPECT_NE(interrupted->error, "");
    EXPECT_GT(interrupted->finishedAt, 0);
    EXPECT_EQ(interrupted->runsDone, 1) << "its runs are kept";
    EXPECT_EQ(store().studies().info(liveRunning)->state, JobState::Running);
    EXPECT_EQ(store().studies().info(goneDone)->state, JobState::Cancelled);
    // The adopted ones start on b only; a's and b's own are as they were.
    EXPECT_FALSE(store().studies().markRunning(goneQueued1, "node-gone"));
    EXPECT_TRUE(store().studies().markRunning(goneQueued1, "node-b"));
    EXPECT_TRUE(store().studies().markRunning(liveQueued, kNode));
    EXPECT_TRUE(store().studies().markRunning(own, "node-b"));
    EXPECT_TRUE(store().studies().adoptOrphans("node-b", std::chrono::seconds(10)).empty()) << "nothing left to adopt";
}

// A heartbeat older than the window counts as a stopped node; a node's released queued
// studies are adopted at once even while it answers.
TEST_P(StudyStoreConformance, AStaleHeartbeatOrAReleaseLetsAnotherNodeAdopt)
{
    const User alice = addUser("alice");
    store().jobLeases().touchNode(NodeInfo{kNode, "api", "", 0});
    const auto released = addStudy(alice.id);
    const auto kept = addStudy(alice.id, 10, "node-c");
    store().jobLeases().touchNode(NodeInfo{"node-c", "api", "", 0});
    store().studies().releaseQueued(kNode);
    EXPECT_EQ(idsOf(store().studies().adoptOrphans("node-b", std::chrono::seconds(10))), (std::vector<std::int64_t>{released}));
    EXPECT_TRUE(store().studies().markRunning(released, "node-b"));

    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_EQ(idsOf(store().studies().adoptOrphans("node-b", std::chrono::milliseconds(10))), (std::vector<std::int64_t>{kept}))
        << "node-c was last seen 50 ms ago, longer than the 10 ms window";
}

// At most maxActive queued or running studies per owner, whichever node admits them; the
// finished ones do not count, nor other owners' studies.
TEST_P(StudyStoreConformance, CreateAndReopenHoldTheActiveLimit)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    auto create = [&](const User& user, const std::string& node) {
        return store().studies().create(user.id, std::nullopt, "sweep", "s", "{}", 4, node, 2);
    };
    const auto first = create(alice, "node-a");
    ASSERT_TRUE(first);
    ASSERT_TRUE(store().studies().markRunning(*first, "node-a"));
    const auto second = create(alice, "node-b");
    ASSERT_TRUE(second);
    EXPECT_EQ(store().studies().activeCount(alice.id), 2);
    EXPECT_EQ(create(alice, "node-c"), std::nullopt) << "a third active study";
    EXPECT_TRUE(create(bob, "node-c")) << "bob's count is his own";
    ASSERT_TRUE(store().studies().finish(*second, JobState::Cancelled, "", "{}"));
    EXPECT_EQ(store().studies().activeCount(alice.id), 1);
    const auto third = create(alice, "node-c");
    ASSERT_TRUE(third);
    EXPECT_FALSE(store().studies().reopen(*second, "node-b", 2)) << "resuming would make a third";
    ASSERT_TRUE(store().studies().finish(*first, JobState::Done, "", "{}"));
    EXPECT_TRUE(store().studies().reopen(*second, "node-b", 2));
    EXPECT_EQ(store().studies().activeCount(alice.id), 2);
}

// Two nodes admitting the same owner's studies at once admit no more than the limit between them.
TEST_P(StudyStoreConformance, ConcurrentCreatesAdmitNoMoreThanTheLimit)
{
    const User alice = addUser("alice");
    const auto second = db->open();   // another node's connections
    std::atomic<int> admitted{0};
    runAtOnce(4, [&](int i) {
        Storage& storage = i % 2 ? *second : store();
        for (int k = 0; k < 3; ++k)
            if (storage.studies().create(alice.id, std::nullopt, "sweep", "s", "{}", 1, "node-" + std::to_string(i), 3))
                ++admitted;
    });
    EXPECT_EQ(admitted.load(), 3);
    EXPECT_EQ(store().studies().activeCount(alice.id), 3);
}

// Each run keeps the node that ran it.
TEST_P(StudyStoreConformance, RunsKeepTheirNode)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    StudyRun run = okRun(0);
    run.node = "node-x";
    ASSERT_TRUE(store().studies().addRun(id, run, nullptr));
    ASSERT_TRUE(store().studies().addRun(id, okRun(1), nullptr));
    const auto runs = store().studies().runs(id, 0, 10);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].node, "node-x");
    EXPECT_EQ(runs[1].node, "");
}

TEST_P(StudyStoreConformance, ReopenQueuesAnInterruptedOrCancelledStudyWithItsRunsKept)
{
    const User alice = addUser("alice");
    const auto interrupted = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().addRun(interrupted, okRun(0), nullptr));
    ASSERT_TRUE(store().studies().addRun(interrupted, okRun(1), nullptr));
    ASSERT_TRUE(store().studies().finish(interrupted, JobState::Interrupted, "stopped", "{}"));
    const auto cancelled = addStudy(alice.id);
    ASSERT_TRUE(store().studies().finish(cancelled, JobState::Cancelled, "", "{}"));
    const auto done = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().finish(done, JobState::Done, "", "{}"));
    const auto running = addRunningStudy(alice.id);
    const auto queued = addStudy(alice.id);

    for (const auto id : {interrupted, cancelled}) {
        EXPECT_TRUE(store().studies().reopen(id, kNode, kNoLimit));
        const auto info = store().studies().info(id);
        EXPECT_EQ(info->state, JobState::Queued);
        EXPECT_EQ(info->error, "");
        EXPECT_EQ(info->finishedAt, 0);
        EXPECT_FALSE(store().studies().reopen(id, kNode, kNoLimit)) << "queued already";
    }
    const auto resumed = store().studies().info(interrupted);
    EXPECT_EQ(resumed->runsDone, 2) << "the runs it has stay counted";
    EXPECT_EQ(store().studies().runs(interrupted, 0, 10).size(), 2u);
    // It runs again: the runs it lacks are added, the ones it has are refused.
    ASSERT_TRUE(store().studies().markRunning(interrupted, kNode));
    EXPECT_FALSE(store().studies().addRun(interrupted, okRun(1), nullptr));
    EXPECT_TRUE(store().studies().addRun(interrupted, okRun(2), nullptr));
    EXPECT_EQ(store().studies().info(interrupted)->runsDone, 3);

    for (const auto id : {done, running, queued}) EXPECT_FALSE(store().studies().reopen(id, kNode, kNoLimit));
    EXPECT_EQ(store().studies().info(done)->state, JobState::Done);
    EXPECT_EQ(store().studies().info(running)->state, JobState::Running);
    EXPECT_FALSE(store().studies().reopen(queued + 1000, kNode, kNoLimit)) << "no such study";
}

TEST_P(StudyStoreConformance, RemoveDeletesTheStudyWithItsRunsAndResults)
{
    const User alice = addUser("alice");
    const auto id = addRunningStudy(alice.id);
    const auto kept = addRunningStudy(alice.id);
    const std::string blob(1000, 'b');
    ASSERT_TRUE(store().studies().addRun(id, okRun(0), &blob));
    ASSERT_TRUE(store().studies().addRun(id, failedRun(1), nullptr));
    ASSERT_TRUE(store().studies().addRun(kept, okRun(0), &blob));
    EXPECT_TRUE(store().studies().remove(id));
    EXPECT_FALSE(store().studies().info(id));
    EXPECT_FALSE(store().studies().request(id));
    EXPECT_TRUE(store().studies().runs(id, 0, 100).empty());
    EXPECT_FALSE(store().studies().runResult(id, 0));
    EXPECT_EQ(store().studies().storedBytes(alice.id), blob.size()) << "only the other study's result is left";
    EXPECT_FALSE(store().studies().remove(id)) << "gone already";
    EXPECT_EQ(store().studies().runResult(kept, 0), blob);
}

// No store deletes users yet; the schema already takes their studies and runs with them.
TEST_P(StudyStoreConformance, DeletingAUserDeletesItsStudiesAndRuns)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    const auto id = addRunningStudy(alice.id);
    const auto bobs = addRunningStudy(bob.id);
    const std::string blob(500, 'b');
    ASSERT_TRUE(store().studies().addRun(id, okRun(0), &blob));
    ASSERT_TRUE(store().studies().addRun(bobs, okRun(0), &blob));
    const std::string enforceKeys = GetParam() == Backend::SQLite ? "PRAGMA foreign_keys=ON; " : "";
    db->exec(enforceKeys + "DELETE FROM users WHERE id = " + std::to_string(alice.id));
    EXPECT_FALSE(store().studies().info(id));
    EXPECT_TRUE(store().studies().runs(id, 0, 100).empty());
    EXPECT_EQ(store().studies().storedBytes(alice.id), 0u);
    EXPECT_EQ(store().studies().storedBytes(bob.id), blob.size());
}

} // namespace
} // namespace tlmhub::test
