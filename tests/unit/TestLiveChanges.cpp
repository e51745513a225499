// Changes while running (Simulation::changeWhileRunning): a new value between two steps for
// an unconnected input variable or a source's constant, applied from the next step on.
// Results are compared bit for bit, sample by sample.
#include "TestHelpers.h"

#include "core/hmf/HmfLoader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <stop_token>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

// A hydraulic position servo (3 s, 30000 steps) whose reference is the SignalStep `Step`
// (y_0 0.2, y_A 0.5, t_step 1 s) and whose proportional gain is `GainP.k`.
std::unique_ptr<System> loadServo()
{
    const std::string path = sharedDir() + "/hopsan-models/Example Models/Position Servo.hmf";
    if (!std::filesystem::exists(path)) {
        ADD_FAILURE() << "missing shared model " << path;
        return nullptr;
    }
    LoadedModel model = loadHmfFile(path);
    EXPECT_FALSE(model.hasErrors()) << model.firstError();
    return std::move(model.root);
}

// Every logged variable as the bits of its samples, and the time vector, so that == means
// bit for bit.
struct RunBits {
    std::vector<std::uint64_t> time;
    std::vector<std::string> names;
    std::vector<std::vector<std::uint64_t>> samples;
};

std::vector<std::uint64_t> bitsOf(std::span<const double> values)
{
    std::vector<std::uint64_t> bits;
    for (double v : values) bits.push_back(std::bit_cast<std::uint64_t>(v));
    return bits;
}

RunBits runBits(const Simulation& sim)
{
    const ResultView view = sim.results();
    RunBits out{bitsOf(view.time()), {}, {}};
    for (std::size_t i = 0; i < view.numVariables(); ++i) {
        out.names.push_back(view.variable(i).fullName);
        out.samples.push_back(bitsOf(view.data(i)));
    }
    return out;
}

// The servo's reference raised and its gain changed: what every changed run below applies.
void changeServo(Simulation& sim)
{
    ASSERT_TRUE(isOk(sim.changeWhileRunning("Step.y_A", 0.8)));
    ASSERT_TRUE(isOk(sim.changeWhileRunning("GainP.k", 0.04)));
}

// The servo run `steps` steps by runSteps, changed, and run to its end.
RunBits servoChangedAfter(std::size_t steps, unsigned threads = 1)
{
    auto root = loadServo();
    if (!root) return {};
    Result<Simulation> sim = compile(*root);
    EXPECT_TRUE(isOk(sim.status()));
    if (!sim) return {};
    EXPECT_TRUE(isOk(sim->runSteps(steps, {.threads = threads})));
    EXPECT_EQ(sim->takenSteps(), steps);
    changeServo(*sim);
    EXPECT_TRUE(isOk(sim->run({.threads = threads})));
    EXPECT_EQ(sim->state(), SimulationState::Finished);
    return runBits(*sim);
}

// A copy: callers pass liveValues() straight in, a temporary a pointer would outlive.
std::optional<LiveValue> findLive(const std::vector<LiveValue>& values, const std::string& path)
{
    for (const LiveValue& v : values)
        if (v.path == path) return v;
    return std::nullopt;
}

} // namespace

TEST(LiveChanges, AChangeAfterRunStepsEqualsAPausedRunChangedAndContinued)
{
    auto root = loadServo();
    ASSERT_TRUE(root);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(isOk(sim.status()));
    // Paused from the progress callback half way, past the step of the reference (t = 1 s).
    std::stop_source pauser;
    RunOptions options;
    options.pause = pauser.get_token();
    options.progressInterval = 1000;
    options.progress = [&](std::size_t taken, std::size_t total) {
        if (taken >= total / 2) pauser.request_stop();
    };
    ASSERT_TRUE(isOk(sim->run(options)));
    ASSERT_EQ(sim->state(), SimulationState::Paused);
    const std::size_t k = sim->takenSteps();
    ASSERT_GT(k, 10000u);
    changeServo(*sim);
    ASSERT_TRUE(isOk(sim->run()));
    ASSERT_EQ(sim->state(), SimulationState::Finished);

    const RunBits paused = runBits(*sim);
    ASSERT_FALSE(paused.names.empty());
    EXPECT_TRUE(paused.samples == servoChangedAfter(k).samples);
    EXPECT_TRUE(paused.time == servoChangedAfter(k).time);
}

TEST(LiveChanges, AChangeAltersTheResultsOnlyFromItsStepOn)
{
    const std::size_t k = 15000;   // t = 1.5 s, the reference stepped at 1 s
    const RunBits changed = servoChangedAfter(k);
    auto root = loadServo();
    ASSERT_TRUE(root);
    std::optional<Simulation> unchangedRun = runToStop(compile(*root));
    ASSERT_TRUE(unchangedRun);
    const RunBits unchanged = runBits(*unchangedRun);
    ASSERT_EQ(changed.names, unchanged.names);
    ASSERT_EQ(changed.time, unchanged.time);

    // A sample logged at step k or before was taken before the change.
    const std::span<const double> time = unchangedRun->results().time();
    const double changedAt = unchangedRun->startTime() + static_cast<double>(k) * unchangedRun->timestep();
    std::size_t differingVariables = 0;
    for (std::size_t v = 0; v < changed.samples.size(); ++v) {
        bool differs = false;
        for (std::size_t i = 0; i < time.size(); ++i) {
            if (time[i] <= changedAt + 0.5 * unchangedRun->timestep())
                EXPECT_EQ(changed.samples[v][i], unchanged.samples[v][i])
                    << changed.names[v] << " at t=" << time[i];
            else if (changed.samples[v][i] != unchanged.samples[v][i])
                differs = true;
        }
        if (differs) ++differingVariables;
    }
    EXPECT_GT(differingVariables, 0u);
    // The reference itself: 0.2 + 0.5 before the change, 0.2 + 0.8 after it.
    const auto stepOutName = std::find(changed.names.begin(), changed.names.end(), "Step#out#Value");
    ASSERT_NE(stepOutName, changed.names.end());
    const auto stepOut = static_cast<std::size_t>(stepOutName - changed.names.begin());
    EXPECT_EQ(std::bit_cast<double>(changed.samples[stepOut].back()), 0.2 + 0.8);
    EXPECT_EQ(std::bit_cast<double>(unchanged.samples[stepOut].back()), 0.2 + 0.5);
}

TEST(LiveChanges, RunInTwoThreadsEqualsOneThread)
{
    const RunBits oneThread = servoChangedAfter(12345);
    ASSERT_FALSE(oneThread.names.empty());
    const RunBits twoThreads = servoChangedAfter(12345, 2);
    EXPECT_TRUE(twoThreads.samples == oneThread.samples);
    EXPECT_TRUE(twoThreads.time == oneThread.time);
}

TEST(LiveChanges, SourceGainAndLimiterConstantsChangeWhileRunning)
{
    // Constant (1) -> Gain (k 1) -> Limit (-1 .. 1), 100 steps of 10 ms, every step logged.
    System s;
    add(s, "SignalConstant", "Constant");
    add(s, "SignalGain", "Gain");
    add(s, "SignalSaturation", "Limit");
    connectOk(s, "Constant", "y", "Gain", "in");
    connectOk(s, "Gain", "out", "Limit", "in");
    Result<Simulation> sim = compile(s, {0.0, 1.0, 0.01, 101});
    ASSERT_TRUE(isOk(sim.status()));

    // The connected inputs take their values from their connections: not listed.
    std::vector<LiveValue> live = sim->liveValues();
    std::vector<std::string> paths;
    for (const LiveValue& v : live) paths.push_back(v.path);
    EXPECT_EQ(paths, (std::vector<std::string>{"Constant.y", "Gain.k", "Limit.y_upper", "Limit.y_lower"}));
    ASSERT_TRUE(findLive(live, "Limit.y_lower"));
    EXPECT_EQ(findLive(live, "Limit.y_lower")->value, -1.0);

    ASSERT_TRUE(isOk(sim->runSteps(50)));
    ASSERT_TRUE(isOk(sim->changeWhileRunning("Constant.y", 3.0)));
    ASSERT_TRUE(isOk(sim->changeWhileRunning("Gain.k", 2.0)));
    ASSERT_TRUE(isOk(sim->changeWhileRunning("Limit.y_upper", 4.0)));
    ASSERT_TRUE(isOk(sim->changeWhileRunning("Limit.y_upper", 5.0)));   // the later one counts
    live = sim->liveValues();
    ASSERT_TRUE(findLive(live, "Constant.y") && findLive(live, "Gain.k") && findLive(live, "Limit.y_upper"));
    EXPECT_EQ(findLive(live, "Constant.y")->value, 3.0);
    EXPECT_EQ(findLive(live, "Gain.k")->value, 2.0);
    EXPECT_EQ(findLive(live, "Limit.y_upper")->value, 5.0);
    ASSERT_TRUE(isOk(sim->run()));

    const std::vector<double> out = loggedSlot(s, "Limit", "out", "Value");
    ASSERT_EQ(out.size(), 101u);
    EXPECT_EQ(out[50], 1.0);    // 1 * 1, before the change
    EXPECT_EQ(out[51], 5.0);    // 3 * 2 limited to 5, from the next step on
    EXPECT_EQ(out[100], 5.0);
    const std::vector<double> gain = loggedSlot(s, "Gain", "out", "Value");
    EXPECT_EQ(gain[51], 6.0);
    // The model keeps its values: the change is to the run.
    EXPECT_EQ(s.component("Gain")->parameters().find("k#Value")->value, "1");
}

TEST(LiveChanges, ParametersThatNeedARestartAreRefusedWithTheirPath)
{
    auto root = loadServo();
    ASSERT_TRUE(root);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->runSteps(100)));
    // A constant the component reads at its start, an initial value, a node's start value and
    // an input fed by a connection.
    for (const std::string path :
         {"Mass.m", "Integrator.out", "Hydraulic_Volume_Multi_Port.P1#Pressure", "Subtract.in1"}) {
        const Status refused = sim->changeWhileRunning(path, 1.0);
        EXPECT_EQ(refused.code(), StatusCode::RestartRequired) << path << ": " << describe(refused);
        EXPECT_STREQ(refused.codeName(), "restart_required");
        EXPECT_EQ(refused.path(), path);
        EXPECT_NE(refused.message().find(path), std::string::npos) << refused.message();
        EXPECT_FALSE(findLive(sim->liveValues(), path));
    }
    for (const std::string path : {"Step.nothing", "Nobody.y_A", "nothing"}) {
        const Status unknown = sim->changeWhileRunning(path, 1.0);
        EXPECT_EQ(unknown.code(), StatusCode::UnknownParameter) << path << ": " << describe(unknown);
        EXPECT_EQ(unknown.path(), path);
    }
    EXPECT_EQ(sim->changeWhileRunning("Step.y_A", std::nan("")).code(), StatusCode::InvalidParameter);
    EXPECT_EQ(sim->changeWhileRunning("Step.y_A", INFINITY).code(), StatusCode::InvalidParameter);
    // Nothing refused reached the run: it goes on as if unchanged.
    const std::optional<LiveValue> yA = findLive(sim->liveValues(), "Step.y_A");
    ASSERT_TRUE(yA);
    EXPECT_EQ(yA->value, 0.5);
}

TEST(LiveChanges, AnInputItsTypeReadsOnlyAtTheStartNeedsARestart)
{
    // SignalSteadyStateIdentifier sizes its window from wl in initialize() and declares so.
    System s;
    add(s, "SignalSteadyStateIdentifier", "Steady");
    Result<Simulation> sim = compile(s, {0.0, 1.0, 0.01, 11});
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->runSteps(10)));
    const Status refused = sim->changeWhileRunning("Steady.wl", 0.5);
    EXPECT_EQ(refused.code(), StatusCode::RestartRequired) << describe(refused);
    EXPECT_EQ(refused.path(), "Steady.wl");
    const std::vector<LiveValue> live = sim->liveValues();
    EXPECT_FALSE(findLive(live, "Steady.wl"));
    ASSERT_TRUE(findLive(live, "Steady.tol"));   // read every step
    EXPECT_TRUE(isOk(sim->changeWhileRunning("Steady.tol", 2.0)));
}

TEST(LiveChanges, TheServoListsItsReferenceAndGainsWithTheirUnits)
{
    auto root = loadServo();
    ASSERT_TRUE(root);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(isOk(sim.status()));
    const std::vector<LiveValue> live = sim->liveValues();
    const std::optional<LiveValue> tStep = findLive(live, "Step.t_step");
    ASSERT_TRUE(tStep);
    EXPECT_EQ(tStep->value, 1.0);
    EXPECT_EQ(tStep->unit, "s");
    const std::optional<LiveValue> gain = findLive(live, "GainP.k");
    ASSERT_TRUE(gain);
    EXPECT_EQ(gain->value, 0.0264249);
    for (const char* connected : {"GainP.in", "Subtract.in1", "Subtract.in2"})
        EXPECT_FALSE(findLive(live, connected)) << connected;
}

TEST(LiveChanges, OnlyBetweenTheStepsOfAnUnfinishedRun)
{
    auto root = loadServo();
    ASSERT_TRUE(root);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(isOk(sim.status()));
    // From inside a run (its progress callback): refused.
    Status duringRun;
    RunOptions options;
    options.progressInterval = 10000;
    options.progress = [&](std::size_t, std::size_t) { duringRun = sim->changeWhileRunning("Step.y_A", 0.8); };
    ASSERT_TRUE(isOk(sim->runSteps(10000, options)));
    EXPECT_EQ(duringRun.code(), StatusCode::InvalidState) << describe(duringRun);
    // Once finished: refused.
    ASSERT_TRUE(isOk(sim->run()));
    const Status finished = sim->changeWhileRunning("Step.y_A", 0.8);
    EXPECT_EQ(finished.code(), StatusCode::InvalidState);
    EXPECT_STREQ(finished.codeName(), "invalid_state");
    // Once stopped: refused.
    ASSERT_TRUE(isOk(sim->reset()));
    std::stop_source stopper;
    stopper.request_stop();
    EXPECT_FALSE(sim->run({.stop = stopper.get_token()}));
    ASSERT_EQ(sim->state(), SimulationState::Stopped);
    EXPECT_EQ(sim->changeWhileRunning("Step.y_A", 0.8).code(), StatusCode::InvalidState);
}

TEST(LiveChanges, AChangeBeforeTheFirstRunAppliesFromTheFirstStep)
{
    // Changed while compiled equals started (no step), changed and run.
    auto root = loadServo();
    ASSERT_TRUE(root);
    Result<Simulation> sim = compile(*root);
    ASSERT_TRUE(isOk(sim.status()));
    changeServo(*sim);
    const std::optional<LiveValue> yA = findLive(sim->liveValues(), "Step.y_A");
    ASSERT_TRUE(yA);
    EXPECT_EQ(yA->value, 0.8);
    EXPECT_EQ(yA->unit, "");
    ASSERT_TRUE(isOk(sim->run()));
    EXPECT_TRUE(runBits(*sim).samples == servoChangedAfter(0).samples);
}

TEST(LiveChanges, ResetGoesBackToTheModelsValues)
{
    auto root = loadServo();
    ASSERT_TRUE(root);
    std::optional<Simulation> unchangedRun = runToStop(compile(*root));
    ASSERT_TRUE(unchangedRun);
    const RunBits unchanged = runBits(*unchangedRun);

    auto changedRoot = loadServo();
    Result<Simulation> sim = compile(*changedRoot);
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->runSteps(15000)));
    changeServo(*sim);
    ASSERT_TRUE(isOk(sim->run()));
    EXPECT_FALSE(runBits(*sim).samples == unchanged.samples);

    // A change asked for but not yet applied is dropped too.
    ASSERT_TRUE(isOk(sim->reset()));
    const std::optional<LiveValue> yA = findLive(sim->liveValues(), "Step.y_A");
    ASSERT_TRUE(yA);
    EXPECT_EQ(yA->value, 0.5);
    changeServo(*sim);
    ASSERT_TRUE(isOk(sim->reset()));
    ASSERT_TRUE(isOk(sim->run()));
    EXPECT_TRUE(runBits(*sim).samples == unchanged.samples);
    EXPECT_EQ(changedRoot->component("Step")->parameters().find("y_A#Value")->value, "0.5");
}
