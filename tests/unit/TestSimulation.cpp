// The run API: compile -> Simulation -> run / reset / setParameter, and its Status codes.
// Results are compared byte for byte as CSV (the text the hash table in tests/models holds).
#include "TestHelpers.h"

#include "core/ResultTable.h"
#include "core/hmf/HmfLoader.h"

#include <cmath>
#include <filesystem>
#include <stop_token>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

std::string servoPath()
{
    const std::string path = sharedDir() + "/hopsan-models/Example Models/Position Servo.hmf";
    if (!std::filesystem::exists(path)) ADD_FAILURE() << "missing shared model " << path;
    return path;
}

std::unique_ptr<System> load(const std::string& path)
{
    LoadedModel model = loadHmfFile(path);
    EXPECT_FALSE(model.hasErrors()) << model.firstError();
    return std::move(model.root);
}

std::string csvOf(const Simulation& sim) { return ResultTable::fromView(sim.results()).toCsv(); }

std::string freshRunCsv(const std::string& path, const SimulationSettings& settings = {})
{
    auto root = load(path);
    Result<Simulation> sim = compile(*root, settings);
    EXPECT_TRUE(sim) << sim.status().message();
    const Status status = sim->run();
    EXPECT_TRUE(status) << status.message();
    return csvOf(*sim);
}

// Mass on a spring whose stiffness is the system parameter "stiffness" (N/m).
void buildMassSpring(System& s, const std::string& stiffness)
{
    add(s, "MechanicFixedPosition", "Wall");
    add(s, "MechanicTranslationalSpring", "Spring");
    add(s, "MechanicTranslationalMass", "Mass");
    add(s, "MechanicForceTransformer", "Force");
    connectOk(s, "Wall", "Pm1", "Spring", "P1");
    connectOk(s, "Spring", "P2", "Mass", "P1");
    connectOk(s, "Mass", "P2", "Force", "P1");
    ASSERT_TRUE(isOk(s.setSystemParameter("stiffness", stiffness, "double", "", "N/m", false)));
    setParam(s, "Spring", "k#Value", "stiffness");
    setParam(s, "Mass", "m", "1");
    setParam(s, "Mass", "B#Value", "0");
    setParam(s, "Force", "F#Value", "100");
}

// Period of the mass's velocity from its upward zero crossings.
double oscillationPeriod(const Simulation& sim)
{
    const ResultView view = sim.results();
    const auto v = view.data("Mass#P2#Velocity");
    EXPECT_TRUE(v.has_value());
    if (!v) return 0.0;
    const auto t = view.time();
    std::vector<double> up;
    for (std::size_t i = 1; i < v->size(); ++i)
        if ((*v)[i - 1] < 0.0 && (*v)[i] >= 0.0)
            up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-(*v)[i - 1]) / ((*v)[i] - (*v)[i - 1]));
    EXPECT_GE(up.size(), 3u);
    return up.size() < 2 ? 0.0 : (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

} // namespace

TEST(Simulation, RunInPiecesEqualsOneWholeRun)
{
    const std::string whole = freshRunCsv(servoPath());
    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(sim) << sim.status().message();
    ASSERT_TRUE(sim->run(1.0));
    EXPECT_EQ(sim->state(), SimulationState::Paused);
    EXPECT_EQ(sim->takenSteps(), 10000u);
    ASSERT_TRUE(sim->run(1.7, {.threads = 2}));
    ASSERT_TRUE(sim->run(3.0));
    EXPECT_EQ(sim->state(), SimulationState::Finished);
    EXPECT_EQ(csvOf(*sim), whole);
}

TEST(Simulation, RunInSlicesOfStepsEqualsOneWholeRunAndStopsAtTheStopTime)
{
    const std::string whole = freshRunCsv(servoPath());
    // Handed over: the simulation owns the model, nothing else keeps it alive.
    Result<Simulation> sim = compile(load(servoPath()));
    ASSERT_TRUE(sim) << sim.status().message();
    ASSERT_TRUE(sim->runSteps(1));
    EXPECT_EQ(sim->takenSteps(), 1u);
    for (unsigned threads : {2u, RunOptions::autoThreads, 1u}) {
        ASSERT_TRUE(sim->runSteps(7777, {.threads = threads}));
        EXPECT_EQ(sim->state(), SimulationState::Paused);
    }
    ASSERT_TRUE(sim->runSteps(1'000'000));   // more than are left: ends at the stop time
    EXPECT_EQ(sim->state(), SimulationState::Finished);
    EXPECT_EQ(sim->takenSteps(), sim->totalSteps());
    EXPECT_EQ(csvOf(*sim), whole);
}

TEST(Simulation, ResetThenRunEqualsAFreshCompile)
{
    const std::string fresh = freshRunCsv(servoPath());
    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(sim->run());
    ASSERT_TRUE(sim->reset());
    EXPECT_EQ(sim->state(), SimulationState::Compiled);
    ASSERT_TRUE(sim->run());
    EXPECT_EQ(csvOf(*sim), fresh);
    // Also from a run left half way.
    ASSERT_TRUE(sim->reset());
    ASSERT_TRUE(sim->run(1.5));
    ASSERT_TRUE(sim->reset());
    ASSERT_TRUE(sim->run());
    EXPECT_EQ(csvOf(*sim), fresh);
}

TEST(Simulation, SetParameterAndResetEqualsLoadingTheChangedModel)
{
    auto changed = load(servoPath());
    setParam(*changed, "Mass", "m", "250");
    Result<Simulation> reference = compile(*changed);
    ASSERT_TRUE(reference->run());
    const std::string expected = csvOf(*reference);

    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(sim->run());
    const std::string before = csvOf(*sim);
    ASSERT_TRUE(sim->setParameter("Mass.m", "250").isOk());
    ASSERT_TRUE(sim->reset());
    ASSERT_TRUE(sim->run());
    EXPECT_EQ(csvOf(*sim), expected);
    EXPECT_NE(csvOf(*sim), before);
}

TEST(Simulation, ChangedSystemParameterReachesTheExpressionsThatUseIt)
{
    // Period 2*pi*sqrt(m/k): 4x the stiffness halves it. Tolerance 0.5 %.
    System s;
    buildMassSpring(s, "1e4");
    Result<Simulation> sim = compile(s, {0.0, 0.3, 1e-5, 30001});
    ASSERT_TRUE(sim) << sim.status().message();
    ASSERT_TRUE(sim->run());
    const double soft = oscillationPeriod(*sim);
    EXPECT_NEAR(soft, 2.0 * M_PI * std::sqrt(1.0 / 1e4), 0.005 * soft);
    ASSERT_TRUE(sim->setParameter("stiffness", "4e4").isOk());
    ASSERT_TRUE(sim->reset());
    ASSERT_TRUE(sim->run());
    const double stiff = oscillationPeriod(*sim);
    EXPECT_NEAR(stiff, 2.0 * M_PI * std::sqrt(1.0 / 4e4), 0.005 * stiff);
}

TEST(Simulation, ParameterChangesAreCheckedAndOnlyBetweenRuns)
{
    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root);
    const Status unknown = sim->setParameter("Mass.nope", "1");
    EXPECT_EQ(unknown.code(), StatusCode::UnknownParameter);
    EXPECT_EQ(unknown.path(), "Mass.nope");
    EXPECT_EQ(sim->setParameter("Nobody.m", "1").code(), StatusCode::UnknownParameter);
    const Status invalid = sim->setParameter("Mass.m", "no_such_name * 2");
    EXPECT_EQ(invalid.code(), StatusCode::InvalidParameter);
    EXPECT_EQ(root->component("Mass")->parameters().find("m")->value, "100");   // unchanged

    ASSERT_TRUE(sim->run(1.0));
    EXPECT_EQ(sim->setParameter("Mass.m", "200").code(), StatusCode::InvalidState);
    ASSERT_TRUE(sim->run());
    EXPECT_EQ(sim->run().code(), StatusCode::InvalidState);   // finished: reset first
}

TEST(Simulation, LogStorageIsAllocatedWhenARunStarts)
{
    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root, {.logSamples = 301});
    EXPECT_EQ(sim->logSlots(), 0u);
    EXPECT_EQ(sim->results().numSamples(), 0u);
    ASSERT_TRUE(sim->initialise());
    EXPECT_EQ(sim->state(), SimulationState::Initialised);
    EXPECT_EQ(sim->logSlots(), 301u);
    EXPECT_EQ(sim->results().numSamples(), 1u);   // the start sample
    ASSERT_TRUE(sim->run(1.5));
    EXPECT_EQ(sim->results().numSamples(), 151u);
    const ResultView view = sim->results();
    const auto index = view.indexOf("Mass#P1#Position");
    ASSERT_TRUE(index.has_value());
    EXPECT_EQ(view.data(*index).size(), 151u);
    EXPECT_EQ(*view.data("Mass#P1#Position"), view.data(*index));
    EXPECT_FALSE(view.data("Mass#P1#Nothing").has_value());
}

TEST(Simulation, StopTokenEndsTheRun)
{
    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root);
    std::stop_source stopper;
    RunOptions options;
    options.stop = stopper.get_token();
    options.progressInterval = 1000;
    std::size_t lastReport = 0, total = 0;
    options.progress = [&](std::size_t taken, std::size_t steps) {
        lastReport = taken;
        total = steps;
        if (taken >= 5000) stopper.request_stop();
    };
    const Status status = sim->run(options);
    EXPECT_EQ(status.code(), StatusCode::SimulationStopped);
    EXPECT_EQ(sim->state(), SimulationState::Stopped);
    EXPECT_EQ(lastReport, 5000u);
    EXPECT_EQ(total, 30000u);
    EXPECT_LT(sim->takenSteps(), 5002u);
}

TEST(Simulation, RunInSlicesEndedByAPauseRequestEqualsOneWholeRun)
{
    const std::string whole = freshRunCsv(servoPath());
    auto root = load(servoPath());
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(sim) << sim.status().message();
    // A pause asked for before the run: no step is taken.
    std::stop_source early;
    early.request_stop();
    ASSERT_TRUE(sim->run({.pause = early.get_token()}));
    EXPECT_EQ(sim->state(), SimulationState::Paused);
    EXPECT_EQ(sim->takenSteps(), 0u);
    // Pauses asked for from the progress callback, on one thread, two and automatic ones.
    for (unsigned threads : {1u, 2u, RunOptions::autoThreads}) {
        const std::size_t before = sim->takenSteps();
        std::stop_source pauser;
        RunOptions options;
        options.threads = threads;
        options.pause = pauser.get_token();
        options.progressInterval = 500;
        options.progress = [&](std::size_t taken, std::size_t) {
            if (taken >= before + 3000) pauser.request_stop();
        };
        ASSERT_TRUE(sim->run(options));
        EXPECT_EQ(sim->state(), SimulationState::Paused);
        EXPECT_GT(sim->takenSteps(), before);
        EXPECT_LT(sim->takenSteps(), sim->totalSteps());
    }
    ASSERT_TRUE(sim->run());
    EXPECT_EQ(sim->state(), SimulationState::Finished);
    EXPECT_EQ(csvOf(*sim), whole);
}

TEST(Simulation, CompileReportsTheProblemWithItsCodeAndPath)
{
    {
        System s;
        add(s, "MechanicTranslationalMass", "Mass");
        Result<Simulation> sim = compile(s);
        ASSERT_FALSE(sim);
        EXPECT_EQ(sim.status().code(), StatusCode::UnconnectedPort);
        EXPECT_EQ(sim.status().path(), "Mass");
        EXPECT_STREQ(sim.status().codeName(), "unconnected_port");
    }
    {
        System s;
        buildMassSpring(s, "1e4");
        setParam(s, "Mass", "m", "undefined_name + 1");
        Result<Simulation> sim = compile(s);
        ASSERT_FALSE(sim);
        EXPECT_EQ(sim.status().code(), StatusCode::InvalidParameter);
        EXPECT_EQ(sim.status().path(), "Mass.m");
    }
    {
        System s;
        buildMassSpring(s, "1e4");
        EXPECT_EQ(compile(s, {0.0, 1.0, -1e-3}).status().code(), StatusCode::InvalidSettings);
        EXPECT_EQ(compile(s, {1.0, 0.5}).status().code(), StatusCode::InvalidSettings);
    }
}

TEST(Simulation, ComponentThatRefusesToInitialiseGivesInitFailedWithItsPath)
{
    const std::string path =
        sharedDir() + "/hopsan-models/Component Test/AeroComponent Test/FlightRecorderTest.hmf";
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    auto root = load(path);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(sim) << sim.status().message();
    const Status status = sim->run();
    ASSERT_FALSE(status);
    EXPECT_EQ(status.code(), StatusCode::InitFailed) << status.codeName();
    EXPECT_EQ(sim->state(), SimulationState::Failed);
    EXPECT_NE(status.message().find("specify a path for the output file"), std::string::npos)
        << status.message();
    ASSERT_FALSE(status.path().empty());
    const Component* reporter = root->component(status.path());
    ASSERT_NE(reporter, nullptr) << status.path();
    EXPECT_EQ(reporter->typeName(), "AeroFlightRecorder");
}

// Hopsan's SignalStopSimulation ends the run as the model designs it: a status of its own
// with the component's message, the results up to that step, and no error in the log. A
// component's error stops a run as a failure, as before (StopTokenEndsTheRun, Model tests).
TEST(Simulation, AStopComponentEndsTheRunAsDesignedWithItsReason)
{
    const std::string path = sharedDir() + "/hopsan-models/Component Test/SignalComponent Test/Logic/StopTest.hmf";
    auto root = load(path);
    ASSERT_TRUE(root);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(sim) << sim.status().message();
    const Status status = sim->run();
    EXPECT_EQ(status.code(), StatusCode::SimulationEnded) << status.message();
    EXPECT_STREQ(status.codeName(), "simulation_ended");
    EXPECT_EQ(status.message(), "Simulation stopped by Stop_simulation");
    EXPECT_EQ(status.path(), "Stop_simulation");
    EXPECT_EQ(sim->state(), SimulationState::Stopped);
    // The step input turns true at t = 5 s of 10: the run ends at that step.
    EXPECT_NEAR(sim->time(), 5.0, 2e-3);
    EXPECT_LT(sim->takenSteps(), sim->totalSteps());
    for (const Message& m : sim->messages())
        EXPECT_NE(m.type, MessageType::Error) << m.text;
    const ResultView view = sim->results();
    ASSERT_FALSE(view.time().empty());
    EXPECT_NEAR(view.time().back(), 5.0, 0.02);
}
