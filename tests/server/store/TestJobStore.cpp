// JobStore's contract (server/store/JobStore.h) on both back ends.
#include "StoreBackends.h"

#include "server/store/JobLeaseStore.h"
#include "server/store/UnixTime.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class JobStoreConformance : public StoreTest {
protected:
    // A job of `ownerId` on model `modelId` with `parameters` as its overrides, finished (done,
    // with a result) unless `finished` is false.
    std::int64_t addModelRun(std::int64_t ownerId, std::int64_t modelId,
                             std::map<std::string, std::string> parameters = {}, bool finished = true)
    {
        JobRequest request = jobRequest(ownerId);
        request.modelId = modelId;
        request.parameters = std::move(parameters);
        const std::int64_t id = store().jobs().create(request, resolvedSettings());
        const std::string blob = "result of " + std::to_string(id);
        if (finished && (!store().jobs().markRunning(id) || !store().jobs().finish(id, JobState::Done, "", 10, &blob)))
            throw std::runtime_error("cannot finish job " + std::to_string(id));
        return id;
    }
};
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

// keep: false comes back from the stored request (what GET /jobs/{id}/results reads).
TEST_P(JobStoreConformance, AnUnkeptRequestComesBackUnkept)
{
    JobRequest request = jobRequest(3);
    request.keep = false;
    const std::int64_t unkept = store().jobs().create(request, resolvedSettings());
    const std::int64_t kept = store().jobs().create(jobRequest(3), resolvedSettings());
    EXPECT_FALSE(store().jobs().request(unkept)->keep);
    EXPECT_TRUE(store().jobs().request(kept)->keep);
}

// One job's results dropped: once (the call that dropped them says so), and only a finished job's.
TEST_P(JobStoreConformance, DropResultsDropsAFinishedJobsResultsOnce)
{
    const std::string blob(1000, 'r');
    const std::int64_t done = addFinishedJob(4, &blob);
    const std::int64_t queued = addJob(4);
    ASSERT_TRUE(store().results().has(done));
    EXPECT_FALSE(store().jobs().dropResults(queued)) << "not finished";
    EXPECT_TRUE(store().jobs().dropResults(done));
    EXPECT_FALSE(store().results().has(done));
    EXPECT_TRUE(store().jobs().info(done)->resultsDropped);
    EXPECT_FALSE(store().jobs().dropResults(done)) << "gone already";
    EXPECT_FALSE(store().jobs().dropResults(done + 1000)) << "no such job";
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

TEST_P(JobStoreConformance, ListForModelIsNewestFirstWithOverridesPagedAndOptionallyOneOwners)
{
    const std::int64_t a1 = addModelRun(1, 10, {{"Gain.k", "2"}, {"mass", "1e400"}});
    const std::int64_t b1 = addModelRun(2, 10);
    addModelRun(1, 11);   // another model
    const std::int64_t a2 = addModelRun(1, 10, {}, false);
    const std::int64_t b2 = addModelRun(2, 10, {{"Sub$Mass.m", "a+b"}});

    const auto all = store().jobs().listForModel(10, std::nullopt, std::nullopt, 100);
    EXPECT_EQ(idsOf(all), (std::vector<std::int64_t>{b2, a2, b1, a1}));
    ASSERT_EQ(all.size(), 4u);
    ASSERT_TRUE(all[3].parameters);
    EXPECT_EQ(*all[3].parameters, (std::map<std::string, std::string>{{"Gain.k", "2"}, {"mass", "1e400"}}));
    EXPECT_EQ(*all[0].parameters, (std::map<std::string, std::string>{{"Sub$Mass.m", "a+b"}}));
    EXPECT_TRUE(all[2].parameters && all[2].parameters->empty());
    EXPECT_EQ(all[1].state, JobState::Queued);
    EXPECT_EQ(all[0].modelId, 10);

    EXPECT_EQ(idsOf(store().jobs().listForModel(10, 1, std::nullopt, 100)), (std::vector<std::int64_t>{a2, a1}));
    // Pages: two, then the two below the last id of the first page.
    const auto first = store().jobs().listForModel(10, std::nullopt, std::nullopt, 2);
    EXPECT_EQ(idsOf(first), (std::vector<std::int64_t>{b2, a2}));
    EXPECT_EQ(idsOf(store().jobs().listForModel(10, std::nullopt, first.back().id, 2)),
              (std::vector<std::int64_t>{b1, a1}));
    EXPECT_TRUE(store().jobs().listForModel(10, std::nullopt, a1, 2).empty());
    EXPECT_TRUE(store().jobs().listForModel(12, std::nullopt, std::nullopt, 2).empty());
    // The other lists carry no overrides.
    EXPECT_FALSE(store().jobs().info(a1)->parameters);
}

TEST_P(JobStoreConformance, LabelSetsNameAndPinnedWhereGiven)
{
    const std::int64_t id = addModelRun(1, 10);
    const JobInfo fresh = *store().jobs().info(id);
    EXPECT_EQ(fresh.name, "");
    EXPECT_FALSE(fresh.pinned);
    EXPECT_FALSE(fresh.resultsDropped);
    ASSERT_TRUE(store().jobs().label(id, std::string("stiffer spring \xc2\xb5"), std::nullopt));
    EXPECT_EQ(store().jobs().info(id)->name, "stiffer spring \xc2\xb5");
    EXPECT_FALSE(store().jobs().info(id)->pinned);
    ASSERT_TRUE(store().jobs().label(id, std::nullopt, true));
    EXPECT_EQ(store().jobs().info(id)->name, "stiffer spring \xc2\xb5") << "a name not given stays";
    EXPECT_TRUE(store().jobs().info(id)->pinned);
    ASSERT_TRUE(store().jobs().label(id, std::string(), false));
    EXPECT_EQ(store().jobs().info(id)->name, "");
    EXPECT_FALSE(store().jobs().info(id)->pinned);
    EXPECT_FALSE(store().jobs().label(id + 100, std::string("x"), true));
}

TEST_P(JobStoreConformance, CreateFinishedStoresADoneJobThatNoClaimTakes)
{
    // The same run stored the three-call way (create, markRunning, finish, label) to compare.
    const std::int64_t ranBefore = addModelRun(1, 10, {{"Gain.k", "2"}});
    ASSERT_TRUE(store().jobs().label(ranBefore, std::string("ran"), std::nullopt));
    const std::int64_t queued = addModelRun(1, 10, {}, false);

    JobRequest request = jobRequest(1);
    request.modelId = 10;
    request.parameters = {{"Gain.k", "2"}};
    const std::string blob("recorded\0bytes\xff", 15);   // bytes a text round trip would change
    const long long before = unixNow();
    const std::int64_t id =
        store().jobs().createFinished(request, resolvedSettings(), 10, blob, "live session 3 (recorded) \xc2\xb5");
    const long long after = unixNow();
    EXPECT_GT(id, queued);

    // No node's claim takes it: right after, a claim hands out the queued job and nothing else.
    ClaimRequest claim;
    claim.nodeId = "node-a";
    claim.count = 10;
    claim.maxRunningPerUser = 10;
    claim.leaseTime = std::chrono::milliseconds(60'000);
    const auto claimed = store().jobLeases().claim(claim);
    ASSERT_EQ(claimed.size(), 1u);
    EXPECT_EQ(claimed[0].jobId, queued);
    EXPECT_TRUE(store().jobLeases().claim(claim).empty());
    EXPECT_FALSE(store().jobLeases().holder(id));
    EXPECT_TRUE(store().jobs().listInState(JobState::Queued).empty());

    const JobInfo info = *store().jobs().info(id);
    const JobInfo ran = *store().jobs().info(ranBefore);
    EXPECT_EQ(info.state, JobState::Done);
    EXPECT_EQ(info.ownerId, 1);
    EXPECT_EQ(info.modelId, 10);
    EXPECT_EQ(info.progress, 1.0);
    EXPECT_EQ(info.error, "");
    EXPECT_EQ(info.steps, 10u);
    EXPECT_EQ(info.name, "live session 3 (recorded) \xc2\xb5");
    EXPECT_FALSE(info.pinned);
    EXPECT_FALSE(info.resultsDropped);
    EXPECT_GE(info.createdAt, before);
    EXPECT_LE(info.finishedAt, after);
    EXPECT_GE(info.startedAt, info.createdAt);
    EXPECT_GE(info.finishedAt, info.startedAt);
    EXPECT_GT(info.startedAt, 0);
    EXPECT_TRUE(sameBits(info.start, ran.start));
    EXPECT_TRUE(sameBits(info.step, ran.step));
    EXPECT_TRUE(sameBits(info.stop, ran.stop));
    EXPECT_EQ(info.logSamples, ran.logSamples);
    EXPECT_TRUE(store().results().has(id));
    EXPECT_EQ(store().results().blob(id), blob);
    EXPECT_EQ(store().jobs().requestText(id), store().jobs().requestText(ranBefore));
    EXPECT_EQ(store().jobs().listInState(JobState::Done).back().id, id);

    // In the model's history like a run that finished, with its overrides.
    const auto history = store().jobs().listForModel(10, std::nullopt, std::nullopt, 100);
    ASSERT_EQ(idsOf(history), (std::vector<std::int64_t>{id, queued, ranBefore}));
    EXPECT_EQ(history[0].state, JobState::Done);
    EXPECT_EQ(history[0].name, info.name);
    EXPECT_EQ(history[0].parameters, history[2].parameters);
    EXPECT_EQ(history[0].usedParameters, history[2].usedParameters);
    EXPECT_EQ(idsOf(store().jobs().listForModel(10, 1, std::nullopt, 100)), idsOf(history));
    // And its results are dropped like a finished run's.
    EXPECT_EQ(store().jobs().dropOldResults(10, 0), 2);
    EXPECT_FALSE(store().results().has(id));
    EXPECT_TRUE(store().jobs().info(id)->resultsDropped);
}

TEST_P(JobStoreConformance, DropOldResultsKeepsTheNewestUnpinnedAndEveryPinnedRun)
{
    const std::int64_t oldest = addModelRun(1, 10);
    const std::int64_t pinnedOld = addModelRun(1, 10);
    ASSERT_TRUE(store().jobs().label(pinnedOld, std::nullopt, true));
    const std::int64_t second = addModelRun(2, 10);   // owners do not matter: the model's runs
    const std::int64_t otherModel = addModelRun(1, 11);
    const std::int64_t third = addModelRun(1, 10);
    const std::int64_t newest = addModelRun(1, 10);
    const std::int64_t queued = addModelRun(1, 10, {}, false);

    EXPECT_EQ(store().jobs().dropOldResults(10, 2), 2);
    for (const std::int64_t gone : {oldest, second}) {
        EXPECT_FALSE(store().results().has(gone)) << gone;
        EXPECT_TRUE(store().jobs().info(gone)->resultsDropped) << gone;
        EXPECT_EQ(store().jobs().info(gone)->state, JobState::Done) << "the run stays listed";
    }
    for (const std::int64_t kept : {pinnedOld, otherModel, third, newest}) {
        EXPECT_TRUE(store().results().has(kept)) << kept;
        EXPECT_FALSE(store().jobs().info(kept)->resultsDropped) << kept;
    }
    EXPECT_FALSE(store().jobs().info(queued)->resultsDropped);
    EXPECT_EQ(store().jobs().dropOldResults(10, 2), 0) << "nothing more to drop";
    // Unpinning the old run makes it the oldest unpinned one with results.
    ASSERT_TRUE(store().jobs().label(pinnedOld, std::nullopt, false));
    EXPECT_EQ(store().jobs().dropOldResults(10, 2), 1);
    EXPECT_FALSE(store().results().has(pinnedOld));
    EXPECT_EQ(store().jobs().dropOldResults(10, 0), 2);
    EXPECT_TRUE(store().results().has(otherModel));
}

TEST_P(JobStoreConformance, RemoveFinishedBeforeKeepsPinnedJobs)
{
    const std::string blob = "pinned result";
    const std::int64_t pinned = addFinishedJob(1, &blob);
    const std::int64_t unpinned = addFinishedJob(1, &blob);
    ASSERT_TRUE(store().jobs().label(pinned, std::nullopt, true));
    waitForNextSecond();
    EXPECT_EQ(store().jobs().removeFinishedBefore(unixNow() + 1), 1);
    EXPECT_FALSE(store().jobs().info(unpinned));
    EXPECT_TRUE(store().jobs().info(pinned));
    EXPECT_EQ(store().results().blob(pinned), blob);
}

} // namespace
} // namespace tlmhub::test
