// StudyStore's contract (server/store/StudyStore.h) on both back ends.
#include "StoreBackends.h"

#include "server/store/UnixTime.h"

#include <atomic>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class StudyStoreConformance : public StoreTest {
protected:
    std::int64_t addStudy(std::int64_t ownerId, std::int64_t runsTotal = 10)
    {
        const auto id = store().studies().create(ownerId, std::nullopt, "sweep", "study", "{}", runsTotal);
        if (!id) throw std::runtime_error("cannot add a study of " + std::to_string(ownerId));
        return *id;
    }
    std::int64_t addRunningStudy(std::int64_t ownerId)
    {
        const std::int64_t id = addStudy(ownerId);
        if (!store().studies().markRunning(id)) throw std::runtime_error("cannot start study " + std::to_string(id));
        return id;
    }
};
TLMHUB_STORE_CONFORMANCE(StudyStoreConformance);

StudyRun okRun(std::int64_t index)
{
    return StudyRun{index, true, R"({"Pump.Dp":)" + std::to_string(index) + "}", R"({"Mass#P1#x:final":0.5})", "", false};
}

StudyRun failedRun(std::int64_t index)
{
    return StudyRun{index, false, R"({"Pump.Dp":-1})", "{}", "the model diverged", false};
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
    const auto id = store().studies().create(alice.id, 42, "sweep", "pump size \xc3\xa5", request, 12);
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
    const auto id = store().studies().create(alice.id, std::nullopt, "optimise", "pid", "{}", 200);
    ASSERT_TRUE(id);
    EXPECT_EQ(store().studies().info(*id)->modelId, std::nullopt);
}

TEST_P(StudyStoreConformance, CreateForAMissingOwnerIsRefused)
{
    EXPECT_EQ(store().studies().create(4242, std::nullopt, "sweep", "orphan", "{}", 1), std::nullopt);
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
    ASSERT_TRUE(store().studies().markRunning(s3));
    ASSERT_TRUE(store().studies().markRunning(s1));
    EXPECT_EQ(idsOf(store().studies().listInState(JobState::Running)), (std::vector<std::int64_t>{s1, s3}));
    EXPECT_EQ(idsOf(store().studies().listInState(JobState::Queued)), (std::vector<std::int64_t>{s2, s4}));
    EXPECT_TRUE(store().studies().listInState(JobState::Done).empty());
}

TEST_P(StudyStoreConformance, MarkRunningStartsOnlyAQueuedStudy)
{
    const User alice = addUser("alice");
    const auto id = addStudy(alice.id);
    const long long before = unixNow();
    EXPECT_TRUE(store().studies().markRunning(id));
    const auto info = store().studies().info(id);
    EXPECT_EQ(info->state, JobState::Running);
    EXPECT_GE(info->startedAt, before);
    EXPECT_FALSE(store().studies().markRunning(id)) << "running already";
    EXPECT_FALSE(store().studies().markRunning(id + 1000));
    ASSERT_TRUE(store().studies().finish(id, JobState::Done, "", "{}"));
    EXPECT_FALSE(store().studies().markRunning(id)) << "finished";
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

TEST_P(StudyStoreConformance, MarkRunningInterruptedEndsOnlyRunningStudies)
{
    const User alice = addUser("alice");
    const auto running1 = addRunningStudy(alice.id);
    const auto queued = addStudy(alice.id);
    const auto running2 = addRunningStudy(alice.id);
    const auto done = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().finish(done, JobState::Done, "", "{}"));
    EXPECT_EQ(store().studies().markRunningInterrupted(), 2);
    for (const auto id : {running1, running2}) {
        const auto info = store().studies().info(id);
        EXPECT_EQ(info->state, JobState::Interrupted);
        EXPECT_NE(info->error, "");
        EXPECT_GT(info->finishedAt, 0);
    }
    EXPECT_EQ(store().studies().info(queued)->state, JobState::Queued);
    EXPECT_EQ(store().studies().info(done)->state, JobState::Done);
    EXPECT_EQ(store().studies().markRunningInterrupted(), 0);
}

TEST_P(StudyStoreConformance, ReopenQueuesAnInterruptedOrCancelledStudyWithItsRunsKept)
{
    const User alice = addUser("alice");
    const auto interrupted = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().addRun(interrupted, okRun(0), nullptr));
    ASSERT_TRUE(store().studies().addRun(interrupted, okRun(1), nullptr));
    ASSERT_EQ(store().studies().markRunningInterrupted(), 1);
    const auto cancelled = addStudy(alice.id);
    ASSERT_TRUE(store().studies().finish(cancelled, JobState::Cancelled, "", "{}"));
    const auto done = addRunningStudy(alice.id);
    ASSERT_TRUE(store().studies().finish(done, JobState::Done, "", "{}"));
    const auto running = addRunningStudy(alice.id);
    const auto queued = addStudy(alice.id);

    for (const auto id : {interrupted, cancelled}) {
        EXPECT_TRUE(store().studies().reopen(id));
        const auto info = store().studies().info(id);
        EXPECT_EQ(info->state, JobState::Queued);
        EXPECT_EQ(info->error, "");
        EXPECT_EQ(info->finishedAt, 0);
        EXPECT_FALSE(store().studies().reopen(id)) << "queued already";
    }
    const auto resumed = store().studies().info(interrupted);
    EXPECT_EQ(resumed->runsDone, 2) << "the runs it has stay counted";
    EXPECT_EQ(store().studies().runs(interrupted, 0, 10).size(), 2u);
    // It runs again: the runs it lacks are added, the ones it has are refused.
    ASSERT_TRUE(store().studies().markRunning(interrupted));
    EXPECT_FALSE(store().studies().addRun(interrupted, okRun(1), nullptr));
    EXPECT_TRUE(store().studies().addRun(interrupted, okRun(2), nullptr));
    EXPECT_EQ(store().studies().info(interrupted)->runsDone, 3);

    for (const auto id : {done, running, queued}) EXPECT_FALSE(store().studies().reopen(id));
    EXPECT_EQ(store().studies().info(done)->state, JobState::Done);
    EXPECT_EQ(store().studies().info(running)->state, JobState::Running);
    EXPECT_FALSE(store().studies().reopen(queued + 1000)) << "no such study";
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
