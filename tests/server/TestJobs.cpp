// Jobs: submit/validate, the fair worker pool, cancel, limits, shutdown/restart, results and
// streamed frames.
#include "TestFiles.h"

#include "core/ResultTable.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "server/jobs/JobQueue.h"
#include "server/jobs/PreparedJob.h"
#include "server/jobs/StreamHub.h"
#include "server/store/Storage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

using namespace tlmhub;
using namespace tlmhub::server;
using tlmhub::test::readFile;

namespace {

const std::string kExample = std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf";
const std::string kServo =
    std::string(TLMHUB_SOURCE_DIR) + "/../shared/hopsan-models/Example Models/Position Servo.hmf";

bool waitUntil(const std::function<bool()>& condition, std::chrono::seconds timeout = std::chrono::seconds(60))
{
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
        if (condition()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return condition();
}

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The result of running a model directly with the core's run API, as the CLI does; the
// parameters are changed on the compiled simulation (a job applies them before compiling).
ResultTable directRun(const std::string& hmf, const std::map<std::string, std::string>& parameters = {},
                      std::optional<double> stop = std::nullopt,
                      std::optional<std::size_t> logSamples = std::nullopt)
{
    LoadedModel m = loadHmfString(hmf, "", "direct");
    EXPECT_FALSE(m.hasErrors()) << m.firstError();
    Result<Simulation> sim = compile(*m.root, {.stopTime = stop, .logSamples = logSamples});
    EXPECT_TRUE(sim) << sim.status().message();
    if (!sim) return {};
    for (const auto& [k, v] : parameters) {
        const Status set = sim->setParameter(k, v);
        EXPECT_TRUE(set) << set.message();
    }
    const Status ran = sim->run();
    EXPECT_TRUE(ran) << ran.message();
    return ResultTable::fromView(sim->results());
}

// Every event a subscription received, thread-safe; frames numbered as a connection that
// keeps up writes them.
struct EventLog {
    std::mutex mutex;
    std::vector<nlohmann::json> events;
    std::uint64_t frames = 0;

    StreamSink sink()
    {
        auto record = [this](nlohmann::json e) {
            std::lock_guard lock(mutex);
            events.push_back(std::move(e));
        };
        StreamSink sink;
        sink.progress = record;
        sink.done = record;
        sink.frame = [this](StreamFrame frame) {
            std::lock_guard lock(mutex);
            events.push_back(nlohmann::json::parse(frame.jsonText(frames++)));
        };
        return sink;
    }
    std::vector<nlohmann::json> snapshot()
    {
        std::lock_guard lock(mutex);
        return events;
    }
    bool done()
    {
        std::lock_guard lock(mutex);
        return !events.empty() && events.back().at("type") == "event.done";
    }
    bool hasFrame()
    {
        std::lock_guard lock(mutex);
        return frames > 0;
    }
};

// Which job's frames and event.done came in which order, across jobs.
struct Timeline {
    std::mutex mutex;
    std::vector<std::pair<std::int64_t, std::string>> events;   // job, event type
    std::map<std::int64_t, std::vector<double>> time;            // streamed time samples per job

    StreamSink sink(std::int64_t job)
    {
        StreamSink sink;
        sink.progress = [](nlohmann::json) {};
        sink.done = [this, job](nlohmann::json) {
            std::lock_guard lock(mutex);
            events.emplace_back(job, "done");
        };
        sink.frame = [this, job](StreamFrame frame) {
            const auto parsed = nlohmann::json::parse(frame.jsonText(0));
            std::lock_guard lock(mutex);
            events.emplace_back(job, "frame");
            for (const auto& t : parsed.at("time")) time[job].push_back(t.get<double>());
        };
        return sink;
    }
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    // Position of the job's first event of that type.
    std::size_t first(std::int64_t job, const std::string& type)
    {
        std::lock_guard lock(mutex);
        for (std::size_t i = 0; i < events.size(); ++i)
            if (events[i] == std::make_pair(job, type)) return i;
        return kNone;
    }
};

class Jobs : public ::testing::Test {
protected:
    std::unique_ptr<Storage> storage = openStorage({.database = ":memory:"});
    JobStore& store = storage->jobs();
    JobLeaseStore& leases = storage->jobLeases();
    ResultStore& results = storage->results();
    StreamHub hub;

    JobRequest request(const std::string& path, std::int64_t owner = 1)
    {
        JobRequest r;
        r.ownerId = owner;
        r.hmf = readFile(path);
        return r;
    }
    // Position Servo running long enough to be cancelled, limited or interrupted.
    JobRequest longRequest(std::int64_t owner = 1)
    {
        JobRequest r = request(kServo, owner);
        r.settings.stop = 4000.0;   // 4e7 steps: far longer than any test waits
        return r;
    }
    JobState state(std::int64_t id) { return store.info(id)->state; }
    bool reaches(std::int64_t id, JobState s)
    {
        return waitUntil([&] { return state(id) == s; });
    }
    bool finishes(std::int64_t id)
    {
        return waitUntil([&] { return isFinished(state(id)); });
    }
    void SetUp() override
    {
        ASSERT_TRUE(std::filesystem::exists(kServo)) << "shared model missing: " << kServo;
    }
};

} // namespace

TEST_F(Jobs, SubmittedJobRunsToDoneWithTheResultOfADirectCoreRun)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    queue.start();
    const auto submitted = queue.submit(request(kExample));
    ASSERT_TRUE(submitted.id) << submitted.code << ": " << submitted.message;
    ASSERT_TRUE(finishes(*submitted.id));
    const JobInfo info = *store.info(*submitted.id);
    EXPECT_EQ(info.state, JobState::Done) << info.error;
    EXPECT_EQ(info.progress, 1.0);
    EXPECT_EQ(info.steps, 20000u);
    EXPECT_EQ(info.start, 0.0);
    EXPECT_EQ(info.stop, 2.0);
    EXPECT_EQ(info.step, 1e-4);
    EXPECT_EQ(info.logSamples, 501u);
    EXPECT_GT(info.startedAt, 0);
    EXPECT_GE(info.finishedAt, info.startedAt);
    const auto result = results.result(*submitted.id);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->toCsv(), directRun(readFile(kExample)).toCsv());
}

TEST_F(Jobs, AJobIsCompiledAtSubmissionAndTheWorkerRunsThatCompiledJob)
{
    JobQueue queue(store, leases, results, hub, {}, 1);   // not started yet: the jobs wait in the queue
    const auto kept = queue.submit(request(kExample));
    const auto cancelled = queue.submit(request(kExample));
    ASSERT_TRUE(kept.id && cancelled.id);
    EXPECT_EQ(queue.compiledQueued(), 2u);
    ASSERT_TRUE(queue.cancel(*cancelled.id));
    EXPECT_EQ(queue.compiledQueued(), 1u);   // a cancelled job's compiled model is freed
    queue.start();
    ASSERT_TRUE(finishes(*kept.id));
    EXPECT_EQ(state(*kept.id), JobState::Done) << store.info(*kept.id)->error;
    EXPECT_EQ(queue.compiledQueued(), 0u);
    EXPECT_EQ(results.result(*kept.id)->toCsv(), directRun(readFile(kExample)).toCsv());
}

TEST_F(Jobs, AJobQueuedBeforeARestartIsCompiledAgainFromItsStoredRequest)
{
    std::int64_t id = 0;
    {
        JobQueue queue(store, leases, results, hub, {}, 1);
        JobRequest r = request(kExample);
        r.parameters = {{"Orifice.Kc", "2e-10"}};
        id = *queue.submit(r).id;
    }   // the server stops before the job ran: its compiled form is gone
    JobQueue restarted(store, leases, results, hub, {}, 1);
    EXPECT_EQ(restarted.compiledQueued(), 0u);
    restarted.start();
    ASSERT_TRUE(finishes(id));
    EXPECT_EQ(state(id), JobState::Done) << store.info(id)->error;
    EXPECT_EQ(results.result(id)->toCsv(), directRun(readFile(kExample), {{"Orifice.Kc", "2e-10"}}).toCsv());
}

TEST_F(Jobs, ParametersAndSettingsOverrideTheModel)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    queue.start();
    JobRequest r = request(kExample);
    r.parameters = {{"Orifice.Kc", "2e-10"}, {"pump_flow", "2e-4"}};
    r.settings.stop = 1.0;
    r.settings.logSamples = 101;
    const auto submitted = queue.submit(r);
    ASSERT_TRUE(submitted.id) << submitted.message;
    ASSERT_TRUE(finishes(*submitted.id));
    ASSERT_EQ(state(*submitted.id), JobState::Done) << store.info(*submitted.id)->error;
    const auto result = results.result(*submitted.id);
    ASSERT_TRUE(result);
    ASSERT_EQ(result->time.size(), 101u);
    EXPECT_NEAR(result->time.back(), 1.0, 1e-9);

    // The same overrides applied directly give the same numbers, and they differ from the
    // model's own values.
    const ResultTable direct =
        directRun(readFile(kExample), {{"Orifice.Kc", "2e-10"}, {"pump_flow", "2e-4"}}, 1.0, 101);
    EXPECT_EQ(result->toCsv(), direct.toCsv());
    const ResultTable plain = directRun(readFile(kExample), {}, 1.0);
    ASSERT_EQ(plain.columns.size(), result->columns.size());
    bool differs = false;
    for (std::size_t c = 0; c < plain.columns.size(); ++c)
        differs = differs || plain.columns[c].data.back() != result->columns[c].data.back();
    EXPECT_TRUE(differs);

    const auto stored = store.request(*submitted.id);
    ASSERT_TRUE(stored);
    EXPECT_EQ(stored->parameters, r.parameters);
    EXPECT_EQ(stored->settings.stop, 1.0);
    EXPECT_EQ(stored->settings.logSamples, 101u);
    EXPECT_FALSE(stored->settings.start);
    EXPECT_EQ(stored->hmf, r.hmf);
}

TEST_F(Jobs, StoredRequestRunsAgainAsANewJob)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    queue.start();
    JobRequest r = request(kExample);
    r.modelId = 7;
    const auto first = queue.submit(r);
    ASSERT_TRUE(first.id);
    ASSERT_TRUE(finishes(*first.id));
    const auto again = queue.submit(*store.request(*first.id));
    ASSERT_TRUE(again.id);
    EXPECT_NE(*again.id, *first.id);
    ASSERT_TRUE(finishes(*again.id));
    EXPECT_EQ(store.info(*again.id)->modelId, 7);
    EXPECT_EQ(results.result(*again.id)->toCsv(), results.result(*first.id)->toCsv());
}

TEST_F(Jobs, WorkersServeUsersRoundRobin)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    std::mutex mutex;
    std::vector<std::int64_t> finishedOrder;
    std::vector<std::int64_t> ids;
    auto record = [&](std::int64_t id) {
        StreamSink sink;
        sink.done = [&, id](nlohmann::json) {
            std::lock_guard lock(mutex);
            finishedOrder.push_back(id);
        };
        sink.progress = [](nlohmann::json) {};
        sink.frame = [](StreamFrame) {};
        return sink;
    };
    for (int i = 0; i < 6; ++i) ids.push_back(*queue.submit(request(kExample, 1)).id);
    const std::int64_t userB = *queue.submit(request(kExample, 2)).id;
    for (auto id : ids) queue.subscribe(id, {}, 0, record(id));
    queue.subscribe(userB, {}, 0, record(userB));
    queue.start();
    ASSERT_TRUE(waitUntil([&] {
        std::lock_guard lock(mutex);
        return finishedOrder.size() == 7;
    }));
    // One worker: B's job takes turns with A's first two (A's limit of started jobs), not
    // after all six of A's.
    const auto positionOfB = std::find(finishedOrder.begin(), finishedOrder.end(), userB) - finishedOrder.begin();
    EXPECT_LT(positionOfB, 3);
}

TEST_F(Jobs, OneWorkerTakesTurnsSoASecondJobStreamsBeforeTheFirstIsDone)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    const auto first = *queue.submit(longRequest(1)).id;
    const auto second = *queue.submit(longRequest(2)).id;
    EventLog firstEvents, secondEvents;
    queue.subscribe(first, {}, 0, firstEvents.sink());
    queue.subscribe(second, {}, 0, secondEvents.sink());
    queue.start();
    ASSERT_TRUE(waitUntil([&] { return firstEvents.hasFrame() && secondEvents.hasFrame(); }));
    // Both started; the one not on the worker waits parked, still running.
    EXPECT_EQ(state(first), JobState::Running);
    EXPECT_EQ(state(second), JobState::Running);
    // One of the two is parked when both are asked to stop at once.
    EXPECT_EQ(queue.requestCancel(first), JobQueue::CancelRequest::Cancelling);
    EXPECT_EQ(queue.requestCancel(second), JobQueue::CancelRequest::Cancelling);
    ASSERT_TRUE(waitUntil([&] { return firstEvents.done() && secondEvents.done(); }));
    EXPECT_EQ(firstEvents.snapshot().back().at("state"), "cancelled");
    EXPECT_EQ(secondEvents.snapshot().back().at("state"), "cancelled");
    EXPECT_EQ(state(first), JobState::Cancelled);
    EXPECT_EQ(state(second), JobState::Cancelled);
    EXPECT_GT(store.info(second)->steps, 0u);
}

TEST_F(Jobs, JobsRunInSlicesStoreTheResultOfAWholeRunAndStreamIt)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    JobRequest r = request(kServo);
    r.settings.stop = 20.0;   // 200000 steps: many slices
    r.settings.logSamples = 20000;
    const auto first = *queue.submit(r).id;
    r.ownerId = 2;
    const auto second = *queue.submit(r).id;
    Timeline timeline;
    queue.subscribe(first, {}, StreamHub::kMaxRate, timeline.sink(first));
    queue.subscribe(second, {}, StreamHub::kMaxRate, timeline.sink(second));
    queue.start();
    ASSERT_TRUE(finishes(first) && finishes(second));
    ASSERT_TRUE(waitUntil([&] {
        return timeline.first(first, "done") != Timeline::kNone && timeline.first(second, "done") != Timeline::kNone;
    }));
    // They took turns: each streamed before the other was done.
    EXPECT_LT(timeline.first(second, "frame"), timeline.first(first, "done"));
    EXPECT_LT(timeline.first(first, "frame"), timeline.first(second, "done"));
    const std::string whole = directRun(readFile(kServo), {}, 20.0, 20000).toCsv();
    for (const auto id : {first, second}) {
        ASSERT_EQ(state(id), JobState::Done) << store.info(id)->error;
        const ResultTable result = *results.result(id);
        EXPECT_EQ(result.toCsv(), whole);
        std::lock_guard lock(timeline.mutex);
        EXPECT_TRUE(bitwiseEqual(timeline.time[id], result.time));
    }
}

TEST_F(Jobs, ShutdownInterruptsParkedJobsToo)
{
    std::int64_t first = 0, second = 0;
    {
        JobQueue queue(store, leases, results, hub, {}, 1);
        first = *queue.submit(longRequest(1)).id;
        second = *queue.submit(longRequest(2)).id;
        EventLog firstEvents, secondEvents;
        queue.subscribe(first, {}, 0, firstEvents.sink());
        queue.subscribe(second, {}, 0, secondEvents.sink());
        queue.start();
        ASSERT_TRUE(waitUntil([&] { return firstEvents.hasFrame() && secondEvents.hasFrame(); }));
        queue.shutdown();
        EXPECT_EQ(state(first), JobState::Interrupted);
        EXPECT_EQ(state(second), JobState::Interrupted);
        EXPECT_EQ(firstEvents.snapshot().back().at("state"), "interrupted");
        EXPECT_EQ(secondEvents.snapshot().back().at("state"), "interrupted");
    }
    JobQueue restarted(store, leases, results, hub, {}, 1);
    restarted.start();
    EXPECT_EQ(state(first), JobState::Interrupted);
    EXPECT_EQ(state(second), JobState::Interrupted);
}

TEST_F(Jobs, AtMostSoManyJobsAreStartedAtOnceTheOthersWaitUnstarted)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    const std::size_t jobs = JobQueue::kMaxStartedJobs + 2;
    std::vector<std::int64_t> ids;
    for (std::size_t i = 0; i < jobs; ++i) ids.push_back(*queue.submit(longRequest(static_cast<std::int64_t>(i) + 1)).id);
    queue.start();
    auto count = [&](JobState s) { return store.listInState(s).size(); };
    ASSERT_TRUE(waitUntil([&] { return count(JobState::Running) == JobQueue::kMaxStartedJobs; }));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(count(JobState::Running), JobQueue::kMaxStartedJobs);
    EXPECT_EQ(count(JobState::Queued), 2u);
    EXPECT_EQ(state(ids.back()), JobState::Queued);
    // A started job ending lets the next one start.
    EXPECT_TRUE(queue.cancel(ids.front()));
    ASSERT_TRUE(waitUntil([&] { return count(JobState::Queued) == 1; }));
    queue.shutdown();
    // Started ones end interrupted; one claimed but not started yet goes back to the queue.
    EXPECT_EQ(count(JobState::Running), 0u);
    EXPECT_GE(count(JobState::Interrupted), JobQueue::kMaxStartedJobs - 1);
    EXPECT_EQ(count(JobState::Interrupted) + count(JobState::Queued), JobQueue::kMaxStartedJobs + 1);
}

TEST_F(Jobs, UserAtRunningLimitWaitsWhileOthersRun)
{
    JobLimits limits;
    limits.maxRunningPerUser = 1;
    JobQueue queue(store, leases, results, hub, limits, 2);
    const auto a1 = *queue.submit(longRequest(1)).id;
    const auto a2 = *queue.submit(longRequest(1)).id;
    const auto b1 = *queue.submit(longRequest(2)).id;
    queue.start();
    ASSERT_TRUE(reaches(a1, JobState::Running));
    ASSERT_TRUE(reaches(b1, JobState::Running));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_EQ(state(a2), JobState::Queued);   // a worker would be free, but A is at its limit
    EXPECT_TRUE(queue.cancel(a1));
    EXPECT_EQ(state(a1), JobState::Cancelled);
    ASSERT_TRUE(reaches(a2, JobState::Running));
    EXPECT_TRUE(queue.cancel(a2));
    EXPECT_TRUE(queue.cancel(b1));
}

TEST_F(Jobs, CancelQueuedAndRunning)
{
    // One started job per user: the second stays queued (not started for a time slice).
    JobLimits limits;
    limits.maxRunningPerUser = 1;
    JobQueue queue(store, leases, results, hub, limits, 1);
    queue.start();
    const auto running = *queue.submit(longRequest()).id;
    const auto queued = *queue.submit(request(kExample)).id;
    EventLog queuedEvents;
    queue.subscribe(queued, {}, 0, queuedEvents.sink());
    ASSERT_TRUE(reaches(running, JobState::Running));
    ASSERT_EQ(state(queued), JobState::Queued);

    EXPECT_TRUE(queue.cancel(queued));
    EXPECT_EQ(state(queued), JobState::Cancelled);
    ASSERT_TRUE(queuedEvents.done());
    EXPECT_EQ(queuedEvents.snapshot().back().at("state"), "cancelled");

    // Cancel in the middle of simulate(): progress is stored from its first callback on.
    ASSERT_TRUE(waitUntil([&] { return store.info(running)->progress > 0.0; }));
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_TRUE(queue.cancel(running));
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
    const JobInfo info = *store.info(running);
    EXPECT_EQ(info.state, JobState::Cancelled);
    EXPECT_GT(info.steps, 0u);
    EXPECT_LT(info.steps, 40'000'000u);
    EXPECT_GT(info.finishedAt, 0);

    EXPECT_FALSE(queue.cancel(running));   // already finished
    EXPECT_FALSE(queue.cancel(12345));     // no such job
}

TEST_F(Jobs, LimitsAreCheckedAtSubmit)
{
    JobLimits limits;
    limits.maxSteps = 10'000;
    limits.maxLogSamples = 500;
    limits.maxQueuedPerUser = 2;
    JobQueue queue(store, leases, results, hub, limits, 1);   // not started: jobs stay queued

    auto tooLong = queue.submit(request(kExample));   // 20000 steps
    EXPECT_FALSE(tooLong.id);
    EXPECT_EQ(tooLong.code, "limit_exceeded");
    EXPECT_NE(tooLong.message.find("20000"), std::string::npos) << tooLong.message;

    JobRequest r = request(kExample);
    r.settings.stop = 0.5;                 // 5000 steps, 501 samples from the model
    auto tooManySamples = queue.submit(r);
    EXPECT_EQ(tooManySamples.code, "limit_exceeded");
    EXPECT_FALSE(tooManySamples.id);

    r.settings.logSamples = 500;
    EXPECT_TRUE(queue.submit(r).id);
    EXPECT_TRUE(queue.submit(r).id);
    auto third = queue.submit(r);
    EXPECT_FALSE(third.id);
    EXPECT_EQ(third.code, "rate_limited") << "room comes as the user's jobs start";
    r.ownerId = 2;
    EXPECT_TRUE(queue.submit(r).id);   // the limit is per user

    r.settings.step = 0.0;
    EXPECT_EQ(queue.submit(r).code, "bad_request");
    EXPECT_EQ(store.listAll().size(), 3u);
}

TEST_F(Jobs, InvalidParametersAndModelsAreRefusedAtSubmit)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    auto submitWith = [&](const std::string& key, const std::string& value) {
        JobRequest r = request(kExample);
        r.parameters[key] = value;
        return queue.submit(r);
    };
    auto unknownName = submitWith("Orifice.Kc", "no_such_name * 2");
    EXPECT_EQ(unknownName.code, "invalid_parameter");
    EXPECT_NE(unknownName.message.find("no_such_name"), std::string::npos) << unknownName.message;
    EXPECT_EQ(submitWith("Orifice.Kc", "1e-10 +").code, "invalid_parameter");
    EXPECT_EQ(submitWith("NoSuchComponent.Kc", "1").code, "invalid_parameter");
    EXPECT_EQ(submitWith("Orifice.NoSuchParameter", "1").code, "invalid_parameter");
    EXPECT_EQ(submitWith("no_such_system_parameter", "1").code, "invalid_parameter");
    // Issue 38: numbers that are not finite, naming the parameter.
    for (const char* notFinite : {"1e400", "nan", "-inf"}) {
        const auto refused = submitWith("Orifice.Kc", notFinite);
        EXPECT_EQ(refused.code, "invalid_parameter") << notFinite;
        EXPECT_NE(refused.message.find("Orifice.Kc"), std::string::npos) << refused.message;
        EXPECT_NE(refused.message.find("not a finite number"), std::string::npos) << refused.message;
    }
    EXPECT_TRUE(submitWith("Orifice.Kc", "relief_pressure * 1e-17").id);   // names resolve
    EXPECT_TRUE(submitWith("Orifice.Kc#Value", "3e-10").id);

    JobRequest broken;
    broken.ownerId = 1;
    broken.hmf = "<hopsanmodelfile><system";
    const auto bad = queue.submit(broken);
    EXPECT_EQ(bad.code, "invalid_model");
    EXPECT_FALSE(bad.message.empty());
    broken.hmf.clear();
    EXPECT_EQ(queue.submit(broken).code, "invalid_model");
    EXPECT_EQ(store.listAll().size(), 2u);
}

// The path syntax itself is tested with the core (TestParameterPath).
TEST_F(Jobs, NestedParametersReachIntoSubsystems)
{
    const std::string path =
        std::string(TLMHUB_SOURCE_DIR) + "/../shared/hopsan-models/Example Models/Sub System Example.hmf";
    JobQueue queue(store, leases, results, hub, {}, 1);
    queue.start();
    JobRequest r = request(path);
    r.parameters = {{"Servo1$Translational_Mass.m", "400"}};
    const auto heavier = queue.submit(r);
    ASSERT_TRUE(heavier.id) << heavier.message;
    const auto plain = queue.submit(request(path));
    ASSERT_TRUE(finishes(*heavier.id) && finishes(*plain.id));
    ASSERT_EQ(state(*heavier.id), JobState::Done);
    const ResultTable a = *results.result(*heavier.id), b = *results.result(*plain.id);
    const ResultColumn* moved = a.column("Servo1$Translational_Mass#P1#Position");
    ASSERT_TRUE(moved);
    EXPECT_NE(moved->data, b.column("Servo1$Translational_Mass#P1#Position")->data);
    EXPECT_EQ(a.column("Servo2$Translational_Mass#P1#Position")->data,
              b.column("Servo2$Translational_Mass#P1#Position")->data);
}

// A model that ends itself with SignalStopSimulation (Hopsan's StopTest: at t = 5 s of 10) has
// run as designed: done, its component's message as the stop reason in the job and in
// event.done, and its results up to that step stored. Before, it ended failed.
TEST_F(Jobs, AModelThatEndsItselfIsDoneWithTheReason)
{
    const std::string stopTest =
        std::string(TLMHUB_SOURCE_DIR) + "/../shared/hopsan-models/Component Test/SignalComponent Test/Logic/StopTest.hmf";
    JobQueue queue(store, leases, results, hub, {}, 1);
    const auto id = *queue.submit(request(stopTest)).id;
    EventLog events;
    queue.subscribe(id, {}, 0, events.sink());
    queue.start();
    ASSERT_TRUE(waitUntil([&] { return events.done(); }));
    const nlohmann::json done = events.snapshot().back();
    EXPECT_EQ(done.at("state"), "done") << done.dump();
    EXPECT_EQ(done.value("stop_reason", ""), "Simulation stopped by Stop_simulation") << done.dump();
    EXPECT_FALSE(done.contains("error")) << done.dump();
    const JobInfo info = *store.info(id);
    EXPECT_EQ(info.state, JobState::Done);
    const nlohmann::json shown = info.toJson();
    EXPECT_EQ(shown.at("error"), "");
    EXPECT_EQ(shown.value("stop_reason", ""), "Simulation stopped by Stop_simulation");
    const auto result = results.result(id);
    ASSERT_TRUE(result);
    ASSERT_FALSE(result->time.empty());
    EXPECT_NEAR(result->time.back(), 5.0, 0.02);
}

TEST_F(Jobs, WallTimeLimitFailsTheJob)
{
    JobLimits limits;
    limits.maxWallSeconds = 0.2;
    JobQueue queue(store, leases, results, hub, limits, 1);
    queue.start();
    const auto t0 = std::chrono::steady_clock::now();
    const auto id = *queue.submit(longRequest()).id;
    ASSERT_TRUE(finishes(id));
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10));
    const JobInfo info = *store.info(id);
    EXPECT_EQ(info.state, JobState::Failed);
    EXPECT_EQ(info.error, "wall time limit (0.2 s) exceeded");
}

TEST_F(Jobs, ResultLargerThanTheLimitFailsTheJob)
{
    JobLimits limits;
    limits.maxResultBytes = 4096;
    JobQueue queue(store, leases, results, hub, limits, 1);
    queue.start();
    const auto id = *queue.submit(request(kExample)).id;
    ASSERT_TRUE(finishes(id));
    const JobInfo info = *store.info(id);
    EXPECT_EQ(info.state, JobState::Failed);
    EXPECT_NE(info.error.find("larger than the limit of 4096 bytes"), std::string::npos) << info.error;
    EXPECT_FALSE(results.result(id));
}

TEST_F(Jobs, ShutdownInterruptsRunningJobsAndRestartRunsTheQueued)
{
    std::int64_t running = 0, queued = 0;
    {
        JobLimits limits;
        limits.maxRunningPerUser = 1;   // the second job stays queued (not started for a time slice)
        JobQueue queue(store, leases, results, hub, limits, 1);
        queue.start();
        running = *queue.submit(longRequest()).id;
        queued = *queue.submit(request(kExample)).id;
        // Started, not only claimed: a claimed job that never started goes back to the queue.
        ASSERT_TRUE(waitUntil([&] { return store.info(running)->progress > 0.0; }));
        queue.shutdown();
        EXPECT_EQ(state(running), JobState::Interrupted);
        EXPECT_EQ(state(queued), JobState::Queued);
    }
    JobQueue restarted(store, leases, results, hub, {}, 1);
    restarted.start();
    ASSERT_TRUE(finishes(queued));
    EXPECT_EQ(state(queued), JobState::Done);
    EXPECT_EQ(state(running), JobState::Interrupted);
}

TEST_F(Jobs, AJobWhoseNodeStoppedRenewingItsLeaseRunsAgainThenIsDead)
{
    JobInfo resolved;
    resolved.stop = 1;
    resolved.step = 0.1;
    const auto again = store.create(request(kExample), resolved);
    // A node that claimed it and then crashed: its lease (50 ms) is never renewed.
    const ClaimRequest crashed{"crashed-node", 1, 2, std::chrono::milliseconds(50), false};
    ASSERT_EQ(leases.claim(crashed).size(), 1u);
    EXPECT_EQ(state(again), JobState::Running);
    QueueNode node;
    node.backoff = std::chrono::milliseconds(10);
    node.pollPeriod = std::chrono::milliseconds(20);
    {
        JobQueue queue(store, leases, results, hub, {}, 1, node);   // another node, or this one restarted
        queue.start();
        ASSERT_TRUE(finishes(again));
        EXPECT_EQ(state(again), JobState::Done) << store.info(again)->error;
        EXPECT_EQ(leases.claims(again), 2);
        EXPECT_EQ(results.result(again)->toCsv(), directRun(readFile(kExample)).toCsv());
    }
    // Claimed as often as a job may be: dead, with the reason.
    const auto dead = store.create(request(kExample), resolved);
    ASSERT_EQ(leases.claim(crashed).size(), 1u);
    node.maxAttempts = 1;
    JobQueue queue(store, leases, results, hub, {}, 1, node);
    queue.start();
    ASSERT_TRUE(finishes(dead));
    EXPECT_EQ(state(dead), JobState::Dead);
    EXPECT_NE(store.info(dead)->error.find("crashed-node"), std::string::npos) << store.info(dead)->error;
    EXPECT_FALSE(results.result(dead));
}

TEST_F(Jobs, StreamedFramesConcatenateToTheStoredResult)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    JobRequest r = request(kServo);
    r.settings.stop = 60.0;   // 600000 steps: long enough for frames during the run
    r.settings.logSamples = 20000;
    const auto id = *queue.submit(r).id;
    EventLog all, picked;
    queue.subscribe(id, {}, 100, all.sink());
    const ResultTable expectedColumns = directRun(readFile(kServo), {}, 0.01);
    ASSERT_GE(expectedColumns.columns.size(), 3u);
    const std::string second = expectedColumns.columns[1].name, first = expectedColumns.columns[0].name;
    queue.subscribe(id, {second, "No#Such#Var", first}, 20, picked.sink());
    queue.start();
    ASSERT_TRUE(finishes(id));
    ASSERT_TRUE(waitUntil([&] { return all.done() && picked.done(); }));
    const ResultTable result = *results.result(id);
    ASSERT_EQ(state(id), JobState::Done);

    auto check = [&](EventLog& log, std::size_t expectVariables) {
        std::vector<double> time;
        std::map<std::string, std::vector<double>> data;
        int frames = 0, progress = 0;
        std::uint64_t seq = 0;
        const auto events = log.snapshot();
        for (const auto& e : events) {
            ASSERT_EQ(e.at("job_id"), id);
            if (e.at("type") == "event.progress") {
                ++progress;
                EXPECT_GE(e.at("progress").get<double>(), 0.0);
                EXPECT_LE(e.at("progress").get<double>(), 1.0);
            }
            if (e.at("type") != "event.frame") continue;
            EXPECT_EQ(e.at("seq").get<std::uint64_t>(), seq++);
            ++frames;
            for (const auto& t : e.at("time")) time.push_back(t.get<double>());
            EXPECT_EQ(e.at("variables").size(), expectVariables);
            for (const auto& [name, values] : e.at("variables").items())
                for (const auto& v : values) data[name].push_back(v.get<double>());
        }
        EXPECT_GE(frames, 2);
        EXPECT_GE(progress, 1);
        EXPECT_EQ(events.back().at("state"), "done");
        EXPECT_TRUE(bitwiseEqual(time, result.time));
        EXPECT_EQ(data.size(), expectVariables);
        for (const auto& [name, values] : data) {
            ASSERT_TRUE(result.hasColumn(name)) << name;
            EXPECT_TRUE(bitwiseEqual(values, result.column(name)->data)) << name;
        }
    };
    check(all, std::min<std::size_t>(result.columns.size(), StreamHub::kMaxFrameVariables));
    check(picked, 2);
    EXPECT_EQ(hub.subscriptionCount(), 0u);   // done ends every subscription
}

TEST_F(Jobs, LateSubscriberGetsEverythingAtOnce)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    queue.start();
    const auto id = *queue.submit(request(kExample)).id;
    ASSERT_TRUE(finishes(id));
    const ResultTable result = *results.result(id);
    EventLog late;
    queue.subscribe(id, {result.columns[2].name}, 0, late.sink());
    const auto events = late.snapshot();   // delivered during subscribe()
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].at("type"), "event.frame");
    EXPECT_EQ(events[0].at("seq"), 0);
    EXPECT_TRUE(bitwiseEqual(events[0].at("time").get<std::vector<double>>(), result.time));
    EXPECT_TRUE(bitwiseEqual(events[0].at("variables").at(result.columns[2].name).get<std::vector<double>>(),
                             result.columns[2].data));
    EXPECT_EQ(events[1].at("type"), "event.done");
    EXPECT_EQ(events[1].at("state"), "done");
    EXPECT_FALSE(events[1].contains("error"));
    EXPECT_EQ(hub.subscriptionCount(), 0u);
}

TEST_F(Jobs, UnsubscribedSinkHearsNothing)
{
    JobQueue queue(store, leases, results, hub, {}, 1);
    const auto id = *queue.submit(request(kExample)).id;
    EventLog gone, kept;
    const auto subscription = queue.subscribe(id, {}, 0, gone.sink());
    queue.subscribe(id, {}, 0, kept.sink());
    hub.unsubscribe(subscription);
    queue.start();
    ASSERT_TRUE(finishes(id));
    ASSERT_TRUE(waitUntil([&] { return kept.done(); }));
    EXPECT_TRUE(gone.snapshot().empty());
}

// A job may use the cores only when it has them to itself: with another job queued or
// running, the workers already use them.
TEST(JobThreads, AutomaticOnlyForAJobAloneOnTheServer)
{
    EXPECT_EQ(jobThreads(false, false), RunOptions::autoThreads);
    EXPECT_EQ(jobThreads(true, false), 1u);
    EXPECT_EQ(jobThreads(false, true), 1u);
    EXPECT_EQ(jobThreads(true, true), 1u);
}

TEST(JobInfo, JsonHasTheApiFields)
{
    JobInfo info;
    info.id = 3;
    info.state = JobState::Running;
    info.createdAt = 100;
    info.startedAt = 101;
    info.steps = 20000;
    info.start = 0;
    info.step = 1e-4;
    info.stop = 2;
    info.logSamples = 501;
    const auto j = info.toJson();
    EXPECT_EQ(j.at("id"), 3);
    EXPECT_TRUE(j.at("model_id").is_null());
    EXPECT_EQ(j.at("state"), "running");
    EXPECT_EQ(j.at("started_at"), 101);
    EXPECT_TRUE(j.at("finished_at").is_null());
    EXPECT_EQ(j.at("settings").at("log_samples"), 501);
    EXPECT_EQ(j.at("settings").at("step"), 1e-4);
    JobState s;
    for (auto st : {JobState::Queued, JobState::Running, JobState::Done, JobState::Failed,
                    JobState::Cancelled, JobState::Interrupted}) {
        ASSERT_TRUE(jobStateFromName(jobStateName(st), s));
        EXPECT_EQ(s, st);
    }
    EXPECT_FALSE(jobStateFromName("paused", s));
}
