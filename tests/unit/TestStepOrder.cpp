// Step order (core.md §3.3, §3.5): S before C before Q; signal components sorted so a value
// propagates through a chain within one step; algebraic loops are refused.
#include "TestHelpers.h"

#include "core/Results.h"

#include <chrono>
#include <thread>

using namespace tlmhub;
using namespace tlmhub::test;

TEST(StepOrder, SignalChainPropagatesWithinOneStepRegardlessOfInsertionOrder)
{
    System s;
    // Inserted reader-first: the sort must still run Step before both gains.
    add(s, "SignalGain", "G2");
    add(s, "SignalGain", "G1");
    add(s, "SignalStep", "Step");
    connectOk(s, "Step", "out", "G1", "in");
    connectOk(s, "G1", "out", "G2", "in");
    setParam(s, "G1", "k#Value", "2");
    setParam(s, "G2", "k#Value", "3");
    setParam(s, "Step", "y_0#Value", "0");
    setParam(s, "Step", "y_A#Value", "1");
    setParam(s, "Step", "t_step#Value", "0.0005");
    ASSERT_TRUE(run(s, 0, 0.003, 0.001, 4));
    Port* out = s.component("G2")->port("out");
    std::vector<double> y = loggedData(*out, 0, s.numLoggedSamples());
    ASSERT_EQ(y.size(), 4u);
    // The step switches in step 1; without sorting G2 would lag by two steps.
    EXPECT_DOUBLE_EQ(y[1], 6.0);
    EXPECT_DOUBLE_EQ(y[3], 6.0);
}

TEST(StepOrder, AlgebraicLoopIsRefused)
{
    System s;
    add(s, "SignalGain", "A");
    add(s, "SignalGain", "B");
    connectOk(s, "A", "out", "B", "in");
    connectOk(s, "B", "out", "A", "in");
    Result<Simulation> sim = compile(s, {.startTime = 0.0, .stopTime = 1.0, .logSamples = 2});
    ASSERT_TRUE(isOk(sim.status()));
    EXPECT_EQ(sim->initialise().code(), StatusCode::AlgebraicLoop);
    bool reported = false;
    for (const auto& m : sim->messages()) reported = reported || m.text.find("algebraic loop") != std::string::npos;
    EXPECT_TRUE(reported);
}

TEST(StepOrder, TimeAdvancesBeforeComponentsAndAccumulates)
{
    System s;
    add(s, "SignalTime", "T");
    add(s, "SignalSink", "Sink");
    connectOk(s, "T", "out", "Sink", "in");
    ASSERT_TRUE(run(s, -1.0, 0.0, 0.001, 1001));
    // Accumulated addition, as Hopsan does: step 1000 from t0=-1 is not exactly 0.
    double t = -1.0;
    for (int i = 0; i < 1000; ++i) t += 0.001;
    EXPECT_EQ(s.logTime().back(), t);
    std::vector<double> y = loggedData(*s.component("T")->port("out"), 0, s.numLoggedSamples());
    EXPECT_EQ(y.back(), t);
}

TEST(StepOrder, RequestStopFromAnotherThreadEndsARunKeepingItsLog)
{
    // A run that could never finish (1e9 steps) is cancelled from another thread; the
    // samples logged so far are kept and the run reports failure.
    System s;
    add(s, "SignalTime", "T");
    add(s, "SignalSink", "Sink");
    connectOk(s, "T", "out", "Sink", "in");
    s.logStartTime = 0.0;
    Result<Simulation> sim = compile(s, {.startTime = 0.0, .stopTime = 1e6, .timestep = 1e-3, .logSamples = 1000001});
    ASSERT_TRUE(isOk(sim.status()));
    // Initialised first: starting clears stop requests, so the canceller's must come after.
    ASSERT_TRUE(isOk(sim->initialise()));
    std::thread canceller([&sim] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        sim->requestStop();
    });
    const Status finished = sim->run();
    canceller.join();
    EXPECT_EQ(finished.code(), StatusCode::SimulationStopped);
    EXPECT_GT(sim->takenSteps(), 0u);
    EXPECT_LT(sim->takenSteps(), 1000000000u);
    EXPECT_GT(sim->results().numSamples(), 0u);
}
