// Multi-threaded simulation gives bitwise the same logs as the single-threaded loop.
#include "TestHelpers.h"

#include "core/hmf/HmfLoader.h"

#include <filesystem>
#include <functional>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

// How a test runs a loaded, compiled model to its stop time.
using ModelRunner = std::function<Status(Simulation& sim)>;

std::vector<std::vector<double>> simulateWith(const std::string& path, const ModelRunner& runModel)
{
    LoadedModel m = loadHmfFile(path);
    EXPECT_FALSE(m.hasErrors()) << m.firstError();
    if (m.hasErrors()) return {};
    Result<Simulation> sim = compile(*m.root);
    EXPECT_TRUE(isOk(sim.status()));
    if (!sim) return {};
    EXPECT_TRUE(isOk(runModel(*sim)));
    return loggedColumns(sim->results());
}

std::vector<std::vector<double>> simulateWith(const std::string& path, unsigned threads)
{
    return simulateWith(path, [threads](Simulation& sim) { return sim.run({.threads = threads}); });
}

class MultiThreading : public ::testing::TestWithParam<const char*> {};

} // namespace

TEST_P(MultiThreading, LogsAreBitwiseEqualToSingleThreaded)
{
    const std::string path = sharedDir() + "/hopsan-models/" + GetParam();
    ASSERT_TRUE(std::filesystem::exists(path)) << "shared model missing: " << path;
    const auto single = simulateWith(path, 1);
    ASSERT_GT(single.size(), 1u);
    for (unsigned threads : {2u}) {
        const auto multi = simulateWith(path, threads);
        ASSERT_EQ(single.size(), multi.size());
        for (std::size_t i = 0; i < single.size(); ++i)
            ASSERT_EQ(single[i], multi[i]) << "column " << i << " with " << threads << " threads";
    }
}

// The automatic thread count ends its threads wherever they stop paying off, also in the
// middle of a run; the logs must not show where. The end is forced: at the first question,
// midway, or never.
TEST_P(MultiThreading, ThreadsEndingAtAnyStepGiveTheSingleThreadedLogs)
{
    const std::string path = sharedDir() + "/hopsan-models/" + GetParam();
    ASSERT_TRUE(std::filesystem::exists(path)) << "shared model missing: " << path;
    const auto single = simulateWith(path, 1);
    ASSERT_GT(single.size(), 1u);
    constexpr std::size_t window = 8;
    enum class End { AtOnce, Midway, Never };
    for (const End end : {End::AtOnce, End::Midway, End::Never}) {
        const char* endName = end == End::AtOnce ? "at once" : end == End::Midway ? "midway" : "never";
        std::size_t totalSteps = 0;
        std::vector<std::size_t> asked;   // the run's steps taken at each question
        unsigned used = 0;
        const auto logs = simulateWith(path, [&](Simulation& sim) {
            if (Status started = sim.initialise(); !started) return started;
            totalSteps = sim.totalSteps();
            const std::size_t endStep = end == End::AtOnce   ? 0
                                        : end == End::Midway ? totalSteps / 2
                                                             : totalSteps + 1;
            const System::KeepThreads keep = [&](std::size_t taken) {
                asked.push_back(taken);
                return taken < endStep;
            };
            // RunOptions cannot force where the threads end, so the initialised System runs.
            const bool finished = sim.system().simulateStepsThreadsWhile(totalSteps, 2, window, keep);
            used = sim.threadsUsed();
            return finished ? Status::ok() : Status{StatusCode::SimulationStopped, "the threaded run stopped early"};
        });
        ASSERT_EQ(single.size(), logs.size());
        for (std::size_t i = 0; i < single.size(); ++i)
            ASSERT_EQ(single[i], logs[i]) << "column " << i << ", threads ending " << endName;
        // Long enough runs end on the thread count forced (a run shorter than its probe and
        // warm-up ends on the threads whatever the check says).
        if (totalSteps > 1000) {
            EXPECT_EQ(used, end == End::Never ? 2u : 1u) << "threads ending " << endName;
            if (end == End::Midway) {
                ASSERT_FALSE(asked.empty());
                EXPECT_LT(asked.front(), totalSteps / 2) << "the threads ran before the middle";
                EXPECT_GE(asked.back(), totalSteps / 2);
                EXPECT_LT(asked.back(), totalSteps / 2 + window) << "they ended at the first question past it";
            }
        }
    }
    // Automatic: whatever it picks on this machine, the logs are the same.
    EXPECT_EQ(simulateWith(path, 0u), single);
}

INSTANTIATE_TEST_SUITE_P(ValidationModels, MultiThreading,
                         ::testing::Values("Example Models/Position Servo.hmf",
                                           "Example Models/Sub System Example.hmf",
                                           "Example Models/Dynamic Pressure Feedback.hmf",
                                           "Example Models/Pressure Relief Valve Characteristics.hmf",
                                           "Example Models/In-Line Axial Piston Machine.hmf",
                                           "Component Test/HydraulicComponent Test/HydraulicLineTest.hmf"));

namespace {

// A 4/3 valve (Q) whose spool position, following a sine command, sets the opening of an
// orifice (Q). The orifice is added first and the valve last, so they fall into different
// regions while both end up last in the sorted Q list: split over two threads they would
// run at the same moment. The orifice must read this step's spool position, after the
// valve, whatever the thread count.
std::vector<double> orificeFlowWithSameStepSignal(unsigned threads)
{
    System s;
    add(s, "HydraulicVolume", "Volume");
    add(s, "HydraulicLaminarOrifice", "Orifice");
    add(s, "HydraulicTankC", "Tank");
    connectOk(s, "Volume", "P2", "Orifice", "P1");
    connectOk(s, "Orifice", "P2", "Tank", "P1");
    for (int k = 0; k < 40; ++k) {   // unrelated filler between the two
        const std::string n = std::to_string(k);
        add(s, "HydraulicPressureSourceC", "FillSource" + n);
        add(s, "HydraulicLaminarOrifice", "FillOrifice" + n);
        add(s, "HydraulicTankC", "FillTank" + n);
        connectOk(s, "FillSource" + n, "P1", "FillOrifice" + n, "P1");
        connectOk(s, "FillOrifice" + n, "P2", "FillTank" + n, "P1");
    }
    add(s, "SignalSineWave", "Command");
    add(s, "HydraulicPressureSourceC", "Supply");
    add(s, "HydraulicTankC", "Return");
    add(s, "HydraulicTankC", "LoadB");
    add(s, "Hydraulic43Valve", "Valve");
    connectOk(s, "Command", "out", "Valve", "in");
    connectOk(s, "Supply", "P1", "Valve", "PP");
    connectOk(s, "Return", "P1", "Valve", "PT");
    connectOk(s, "Volume", "P1", "Valve", "PA");
    connectOk(s, "LoadB", "P1", "Valve", "PB");
    connectOk(s, "Valve", "xv", "Orifice", "Kc");
    setParam(s, "Command", "y_A#Value", "0.005");
    setParam(s, "Command", "f#Value", "20");
    const std::optional<Simulation> sim =
        runToStop(compile(s, {.startTime = 0.0, .stopTime = 0.2, .timestep = 1e-4, .logSamples = 2001}),
                  {.threads = threads});
    if (!sim) return {};
    const std::optional<std::vector<double>> flow = sim->results().data("Orifice#P2#Flow");
    EXPECT_TRUE(flow) << "Orifice#P2#Flow is not logged";
    return flow.value_or(std::vector<double>{});
}

} // namespace

TEST(MultiThreadingPartition, SignalBetweenTwoQComponentsStaysInOrderOnOneThread)
{
    const std::vector<double> single = orificeFlowWithSameStepSignal(1);
    ASSERT_EQ(single.size(), 2001u);
    double largest = 0.0;
    for (double q : single) largest = std::max(largest, std::abs(q));
    ASSERT_GT(largest, 0.0) << "the orifice must pass flow for the test to mean anything";
    for (int run = 0; run < 5; ++run) EXPECT_EQ(orificeFlowWithSameStepSignal(2), single) << "run " << run;
}

// A run far too short to gain from threads does not start them.
TEST(MultiThreadingAuto, ShortRunOfASmallModelStaysOnOneThread)
{
    System s;
    add(s, "HydraulicPressureSourceC", "Source");
    add(s, "HydraulicLaminarOrifice", "Orifice");
    add(s, "HydraulicTankC", "Tank");
    connectOk(s, "Source", "P1", "Orifice", "P1");
    connectOk(s, "Orifice", "P2", "Tank", "P1");
    Result<Simulation> sim = compile(s, {.startTime = 0.0, .stopTime = 1.0});
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->run({.threads = RunOptions::autoThreads})));
    EXPECT_EQ(sim->threadsUsed(), 1u);
    EXPECT_EQ(sim->takenSteps(), 1000u);
}

// A progress callback may read the log while the threads run (a server job streams frames
// this way): a row must count as logged only once every thread has copied its share.
TEST(MultiThreadingLog, ProgressSeesOnlyCompleteRows)
{
    const std::string path = sharedDir() + "/hopsan-models/Example Models/Position Servo.hmf";
    ASSERT_TRUE(std::filesystem::exists(path)) << "shared model missing: " << path;
    LoadedModel m = loadHmfFile(path);
    ASSERT_FALSE(m.hasErrors()) << m.firstError();
    // A row every step, read right after every step.
    Result<Simulation> sim = compile(*m.root, {.startTime = 0.0, .stopTime = 1.0, .timestep = 1e-4, .logSamples = 10001});
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->initialise()));
    const ResultView results = sim->results();
    std::vector<std::pair<std::size_t, std::vector<double>>> seen;   // (row, its values then)
    const auto readLastRow = [&](std::size_t, std::size_t) {
        const std::size_t rows = results.numSamples();
        if (rows == 0) return;
        std::vector<double> row;
        for (const LoggedVariable& v : results.variables()) appendLoggedData(*v.port, v.slot, rows - 1, rows, row);
        seen.emplace_back(rows - 1, std::move(row));
    };
    ASSERT_TRUE(isOk(sim->run({.threads = 2, .progress = readLastRow, .progressInterval = 1})));
    ASSERT_EQ(sim->threadsUsed(), 2u);
    const auto columns = loggedColumns(sim->results());
    ASSERT_GT(seen.size(), 5000u);
    for (const auto& [row, values] : seen)
        for (std::size_t i = 0; i < values.size(); ++i)
            ASSERT_EQ(values[i], columns[i + 1][row]) << results.variable(i).fullName << " in row " << row;
}
