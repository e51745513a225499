// JobStore's contract (server/store/JobStore.h) on both back ends.
#include "StoreBackends.h"

#include "server/store/UnixTime.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class JobStoreConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(JobStoreConformance);

std::vector<std::int64_t> idsOf(const std::vector<JobInfo>& jobs)
{
    std::vector<std::int64_t> ids;
    for (const auto& j : jobs) ids.push_back(j.id);
    return ids;
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST_P(JobStoreConformance, CreateStoresOwnerModelAndResolvedSettingsExactly)
{
    JobRequest request = jobRequest(7);
    request.modelId = 42;
    // Values a float or decimal round trip would change.
    JobInfo resolved;
    resolved.start = -0.1;
    resolved.step = 1e-5 / 3;
    resolved.stop = std::nextafter(10.0, 11.0);
    resolved.steps = 3'000'000'000'123ull;   // beyond 32 bits
    resolved.logSamples = 4097;
    // Fields create ignores.
    resolved.id = 999;
    resolved.ownerId = 999;
    resolved.state = JobState::Done;
    resolved.progress = 0.5;
    resolved.error = "ignored";
    const long long before = unixNow();
    const std::int64_t id = store().jobs().create(request, resolved);
    const long long after = unixNow();
    const auto info = store().jobs().info(id);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->id, id);
    EXPECT_EQ(info->ownerId, 7);
    EXPECT_EQ(info->modelId, 42);
    EXPECT_EQ(info->state, JobState::Queued);
    EXPECT_EQ(info->progress, 0.0);
    EXPECT_EQ(info->error, "");
    EXPECT_GE(info->createdAt, before);
    EXPECT_LE(info->createdAt, after);
    EXPECT_EQ(info->startedAt, 0);
    EXPECT_EQ(info->finishedAt, 0);
    EXPECT_EQ(info->steps, 3'000'000'000'123ull);
    EXPECT_TRUE(sameBits(info->start, resolved.start)) << info->start;
    EXPECT_TRUE(sameBits(info->step, resolved.step)) << info->step;
    EXPECT_TRUE(sameBits(info->stop, resolved.stop)) << info->stop;
    EXPECT_EQ(info->logSamples, 4097u);
    EXPECT_FALSE(store().jobs().info(id + 1000));
}

TEST_P(JobStoreConformance, AJobWithoutAModelHasNoModelId)
{
    const std::int64_t id = addJob(1);
    EXPECT_EQ(store().jobs().info(id)->modelId, std::nullopt);
}

TEST_P(JobStoreConformance, TheRequestComesBackAsItsJsonAndAsARequest)
{
    JobRequest request = jobRequest(3);
    request.modelId = 5;
    request.parameters = {{"Sub$Comp.Param", "1.5e-3"}, {"k", "x \"quoted\" \\ back"}};
    request.settings = {.start = 0.25, .step = 1e-4, .stop = 3.5, .logSamples = 500};
    request.modelDirectory = "/data/models/dir with space";
    const std::int64_t id = store().jobs().create(request, resolvedSettings());
    const auto text = store().jobs().requestText(id);
    ASSERT_TRUE(text);
    // Compared as JSON: a back end may store it as a JSON type that spaces it otherwise.
    EXPECT_EQ(nlohmann::json::parse(*text), request.toJson());
    const auto back = store().jobs().request(id);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->ownerId, 3);
    EXPECT_EQ(back->modelId, 5);
    EXPECT_EQ(back->hmf, request.hmf);
    EXPECT_EQ(back->parameters, request.parameters);
    EXPECT_EQ(back->settings.start, 0.25);
    EXPECT_EQ(back->settings.step, 1e-4);
    EXPECT_EQ(back->settings.stop, 3.5);
    EXPECT_EQ(back->settings.logSamples, 500u);
    EXPECT_EQ(back->modelDirectory, request.modelDirectory);
    EXPECT_FALSE(store().jobs().requestText(id + 1000));
    EXPECT_FALSE(store().jobs().request(id + 1000));
}

TEST_P(JobStoreConformance, RequestIsNothingWhenTheStoredTextIsNotARequest)
{
    const std::int64_t id = addJob(1);
    db->exec("UPDATE jobs SET request = '{\"owner_id\": \"seven\"}' WHERE id = " + std::to_string(id));
    EXPECT_EQ(store().jobs().requestText(id), "{\"owner_id\": \"seven\"}");
    EXPECT_FALSE(store().jobs().request(id));
    EXPECT_TRUE(store().jobs().info(id));
}

TEST_P(JobStoreConformance, ListForOwnerIsNewestFirstAndOnlyThatOwners)
{
    const std::int64_t a1 = addJob(1), b1 = addJob(2), a2 = addJob(1), a3 = addJob(1);
    EXPECT_EQ(idsOf(store().jobs().listForOwner(1)), (std::vector<std::int64_t>{a3, a2, a1}));
    EXPECT_EQ(idsOf(store().jobs().listForOwner(2)), std::vector<std::int64_t>{b1});
    EXPECT_TRUE(store().jobs().listForOwner(3).empty());
}

TEST_P(JobStoreConformance, ListAllHoldsEveryJobWithItsFields)
{
    const std::int64_t a = addJob(1), b = addJob(2);
    store().jobs().markRunning(b);
    auto all = store().jobs().listAll();
    ASSERT_EQ(all.size(), 2u);
    std::sort(all.begin(), all.end(), [](const JobInfo& x, const JobInfo& y) { return x.id < y.id; });
    EXPECT_EQ(all[0].id, a);
    EXPECT_EQ(all[0].ownerId, 1);
    EXPECT_EQ(all[0].state, JobState::Queued);
    EXPECT_EQ(all[1].id, b);
    EXPECT_EQ(all[1].ownerId, 2);
    EXPECT_EQ(all[1].state, JobState::Running);
    EXPECT_EQ(all[1].steps, 2000u);
}

TEST_P(JobStoreConformance, ListInStateIsOldestFirstAndOnlyThatState)
{
    const std::int64_t q1 = addJob(1), r1 = addJob(2), q2 = addJob(2), r2 = addJob(1), q3 = addJob(1);
    ASSERT_TRUE(store().jobs().markRunning(r2));
    ASSERT_TRUE(store().jobs().markRunning(r1));
    EXPECT_EQ(idsOf(store().jobs().listInState(JobState::Queued)), (std::vector<std::int64_t>{q1, q2, q3}));
    EXPECT_EQ(idsOf(store().jobs().listInState(JobState::Running)), (std::vector<std::int64_t>{r1, r2}));
    EXPECT_TRUE(store().jobs().listInState(JobState::Done).empty());
}

TEST_P(JobStoreConformance, CreateWithinQueueLimitRefusesAtTheLimitCountingOnlyThatOwnersQueuedJobs)
{
    std::vector<std::int64_t> admitted;
    for (int i = 0; i < 3; ++i) {
        const auto admission = store().jobs().createWithinQueueLimit(jobRequest(1), resolvedSettings(), 3);
        ASSERT_TRUE(admission.id) << i;
        EXPECT_EQ(admission.queued, i);
        admitted.push_back(*admission.id);
    }
    const auto refused = store().jobs().createWithinQueueLimit(jobRequest(1), resolvedSettings(), 3);
    EXPECT_FALSE(refused.id);
    EXPECT_EQ(refused.queued, 3);
    EXPECT_EQ(store().jobs().listForOwner(1).size(), 3u) << "a refused job is not stored";

    // Another owner's queue is their own; a job that runs no longer counts.
    EXPECT_TRUE(store().jobs().createWithinQueueLimit(jobRequest(2), resolvedSettings(), 3).id);
    ASSERT_TRUE(store().jobs().markRunning(admitted[0]));
    const auto again = store().jobs().createWithinQueueLimit(jobRequest(1), resolvedSettings(), 3);
    ASSERT_TRUE(again.id);
    EXPECT_EQ(again.queued, 2);
    EXPECT_EQ(store().jobs().info(*again.id)->state, JobState::Queued);
    EXPECT_FALSE(store().jobs().createWithinQueueLimit(jobRequest(1), resolvedSettings(), 0).id);
}

TEST_P(JobStoreConformance, MarkRunningOnlyTakesAQueuedJob)
{
    const std::int64_t id = addJob(1);
    const long long before = unixNow();
    EXPECT_TRUE(store().jobs().markRunning(id));
    const long long after = unixNow();
    const JobInfo running = *store().jobs().info(id);
    EXPECT_EQ(running.state, JobState::Running);
    EXPECT_GE(running.startedAt, before);
    EXPECT_LE(running.startedAt, after);
    EXPECT_FALSE(store().jobs().markRunning(id));
    EXPECT_FALSE(store().jobs().markRunning(id + 1000));
    const std::int64_t cancelled = addJob(1);
    ASSERT_TRUE(store().jobs().finish(cancelled, JobState::Cancelled, "", 0, nullptr));
    EXPECT_FALSE(store().jobs().markRunning(cancelled));
    EXPECT_EQ(store().jobs().info(cancelled)->state, JobState::Cancelled);
    EXPECT_EQ(store().jobs().info(cancelled)->startedAt, 0);
}

TEST_P(JobStoreConformance, SetProgressOnlyChangesARunningJob)
{
    const std::int64_t id = addJob(1);
    store().jobs().setProgress(id, 0.5);
    EXPECT_EQ(store().jobs().info(id)->progress, 0.0) << "queued";
    ASSERT_TRUE(store().jobs().markRunning(id));
    store().jobs().setProgress(id, 0.3);
    EXPECT_EQ(store().jobs().info(id)->progress, 0.3);
    store().jobs().setProgress(id, 0.7);
    EXPECT_EQ(store().jobs().info(id)->progress, 0.7);
    ASSERT_TRUE(store().jobs().finish(id, JobState::Failed, "diverged", 10, nullptr));
    store().jobs().setProgress(id, 0.9);
    EXPECT_EQ(store().jobs().info(id)->progress, 0.7) << "finished";
    store().jobs().setProgress(id + 1000, 0.5);
}

TEST_P(JobStoreConformance, FinishStoresStateErrorTakenStepsAndTime)
{
    const std::int64_t id = addJob(1);
    ASSERT_TRUE(store().jobs().markRunning(id));
    store().jobs().setProgress(id, 0.4);
    const long long before = unixNow();
    ASSERT_TRUE(store().jobs().finish(id, JobState::Failed, "solver diverged at t = 1.2 s", 1234, nullptr));
    const long long after = unixNow();
    const JobInfo info = *store().jobs().info(id);
    EXPECT_EQ(info.state, JobState::Failed);
    EXPECT_EQ(info.error, "solver diverged at t = 1.2 s");
    EXPECT_EQ(info.steps, 1234u);
    EXPECT_EQ(info.progress, 0.4) << "only done sets the progress to 1";
    EXPECT_GE(info.finishedAt, before);
    EXPECT_LE(info.finishedAt, after);
    EXPECT_FALSE(store().results().has(id));
    EXPECT_FALSE(store().results().blob(id));
}

TEST_P(JobStoreConformance, FinishDoneSetsProgressToOneAndStoresTheResult)
{
    const std::int64_t id = addJob(1);
    ASSERT_TRUE(store().jobs().markRunning(id));
    store().jobs().setProgress(id, 0.4);
    const std::string blob = "result bytes";
    ASSERT_TRUE(store().jobs().finish(id, JobState::Done, "", 2000, &blob));
    const JobInfo info = *store().jobs().info(id);
    EXPECT_EQ(info.state, JobState::Done);
    EXPECT_EQ(info.progress, 1.0);
    EXPECT_EQ(info.steps, 2000u);
    EXPECT_TRUE(store().results().has(id));
    EXPECT_EQ(store().results().blob(id), blob);
}

TEST_P(JobStoreConformance, FinishTakesAQueuedJob)
{
    const std::int64_t id = addJob(1);
    ASSERT_TRUE(store().jobs().finish(id, JobState::Cancelled, "cancelled by its owner", 0, nullptr));
    const JobInfo info = *store().jobs().info(id);
    EXPECT_EQ(info.state, JobState::Cancelled);
    EXPECT_EQ(info.error, "cancelled by its owner");
    EXPECT_GT(info.finishedAt, 0);
}

TEST_P(JobStoreConformance, FinishRefusesAJobThatIsAlreadyFinished)
{
    const std::int64_t id = addJob(1);
    ASSERT_TRUE(store().jobs().markRunning(id));
    const std::string first = "first";
    ASSERT_TRUE(store().jobs().finish(id, JobState::Done, "", 2000, &first));
    const JobInfo done = *store().jobs().info(id);
    const std::string second = "second";
    for (JobState state : {JobState::Done, JobState::Failed, JobState::Cancelled, JobState::Interrupted})
        EXPECT_FALSE(store().jobs().finish(id, state, "late", 5, &second)) << jobStateName(state);
    const JobInfo after = *store().jobs().info(id);
    EXPECT_EQ(after.state, JobState::Done);
    EXPECT_EQ(after.error, "");
    EXPECT_EQ(after.steps, done.steps);
    EXPECT_EQ(after.finishedAt, done.finishedAt);
    EXPECT_EQ(store().results().blob(id), first);
}

TEST_P(JobStoreConformance, FinishRefusesAnUnknownJob)
{
    const std::string blob = "orphan";
    EXPECT_FALSE(store().jobs().finish(1000, JobState::Done, "", 1, &blob));
    EXPECT_FALSE(store().results().has(1000));
    EXPECT_FALSE(store().jobs().info(1000));
}

TEST_P(JobStoreConformance, RemoveDeletesTheJobAndItsResult)
{
    const std::string blob(5000, 'r');
    const std::int64_t gone = addFinishedJob(1, &blob);
    const std::int64_t kept = addFinishedJob(1, &blob);
    EXPECT_TRUE(store().jobs().remove(gone));
    EXPECT_FALSE(store().jobs().info(gone));
    EXPECT_FALSE(store().jobs().requestText(gone));
    EXPECT_FALSE(store().results().has(gone));
    EXPECT_FALSE(store().results().blob(gone));
    EXPECT_EQ(store().results().storedBytes(1), blob.size());
    EXPECT_FALSE(store().jobs().remove(gone));
    EXPECT_TRUE(store().results().has(kept));
    const std::int64_t queued = addJob(1);
    EXPECT_TRUE(store().jobs().remove(queued));
    EXPECT_EQ(idsOf(store().jobs().listAll()), std::vector<std::int64_t>{kept});
}

TEST_P(JobStoreConformance, RemoveFinishedBeforeRemovesOnlyJobsFinishedEarlierAndTheirResults)
{
    const std::string blob = "old result";
    const std::int64_t oldDone = addFinishedJob(1, &blob);
    const std::int64_t oldFailed = addJob(2);
    ASSERT_TRUE(store().jobs().finish(oldFailed, JobState::Failed, "x", 0, nullptr));
    const std::int64_t queued = addJob(1), running = addJob(1);
    ASSERT_TRUE(store().jobs().markRunning(running));
    waitForNextSecond();
    const std::int64_t cutoff = unixNow();
    const std::int64_t recent = addFinishedJob(1, &blob);
    EXPECT_EQ(store().jobs().removeFinishedBefore(cutoff - 100), 0);
    EXPECT_EQ(store().jobs().removeFinishedBefore(cutoff), 2);
    EXPECT_FALSE(store().jobs().info(oldDone));
    EXPECT_FALSE(store().jobs().info(oldFailed));
    EXPECT_FALSE(store().results().has(oldDone));
    EXPECT_EQ(store().results().storedBytes(1), blob.size()) << "only the recent job's result is left";
    auto left = idsOf(store().jobs().listAll());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::int64_t>{queued, running, recent}));
    // Unfinished jobs stay however old they are.
    EXPECT_EQ(store().jobs().removeFinishedBefore(cutoff + 100), 1);
    EXPECT_TRUE(store().jobs().info(queued));
    EXPECT_TRUE(store().jobs().info(running));
}

} // namespace
} // namespace tlmhub::test
