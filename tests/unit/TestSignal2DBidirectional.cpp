// The 2D signal types with bidirectional ports (Hopsan's Signal2DWriteRead,
// Signal2DReadWrite and Signal2DSplit): a pair passes one value each way over one node,
// sorted writer first; sh2d lets the pair break a loop; Split sends each dimension the way
// its scalar side asks; what such ports may and may not be connected to.
#include "TestHelpers.h"

#include "core/Results.h"
#include "core/hmf/HmfLoader.h"
#include "core/hmf/HmfSaver.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace sig2dbidir {

std::vector<double> valuesOf(System& s, const std::string& comp, const std::string& port)
{
    return loggedSlot(s, comp, port, "Value");
}

// Sine -> WR.write, Clock -> RW.write, WR.P2d <-> RW.P2d. The reading end is added first
// and the sources last, so only the sort can run them in data-flow order.
void buildPair(System& s)
{
    add(s, "Signal2DReadWrite", "RW");
    add(s, "Signal2DWriteRead", "WR");
    add(s, "SignalSineWave", "Sine");
    add(s, "SignalTime", "Clock");
    setParam(s, "Sine", "f#Value", "7");
    setParam(s, "Sine", "y_A#Value", "2.5");
    connectOk(s, "Sine", "out", "WR", "write");
    connectOk(s, "Clock", "out", "RW", "write");
    connectOk(s, "WR", "P2d", "RW", "P2d");
}

// RW.read -> Add.in1 (in2 = 1) -> WR.write: each step adds one to what went round before,
// which only the sh2d = IndependentDestination option lets the sort order.
void buildLoop(System& s, const std::string& sh2d)
{
    add(s, "Signal2DWriteRead", "WR");
    add(s, "Signal2DReadWrite", "RW");
    add(s, "SignalAdd", "Add");
    setParam(s, "RW", "sh2d", sh2d);
    setParam(s, "Add", "in2#Value", "1");
    connectOk(s, "WR", "P2d", "RW", "P2d");
    connectOk(s, "RW", "read", "Add", "in1");
    connectOk(s, "Add", "out", "WR", "write");
}

bool allFinite(const std::vector<double>& values)
{
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return !values.empty();
}

} // namespace sig2dbidir

using namespace sig2dbidir;

TEST(Signal2DBidirectional, PairCarriesOneValueEachWay)
{
    System s;
    buildPair(s);
    ASSERT_TRUE(run(s, 0, 0.2, 1e-3, 201));
    const auto& t = s.logTime();
    const auto sine = valuesOf(s, "Sine", "out");
    const auto forward = valuesOf(s, "RW", "read");    // v0, written by WR
    const auto backward = valuesOf(s, "WR", "read");   // v1, written by RW
    ASSERT_EQ(forward.size(), t.size());
    ASSERT_EQ(backward.size(), t.size());
    // Forward, WR before RW: the value of this very step, exactly.
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(forward[i], sine[i]) << "t=" << t[i];
    // Backward: WR has already run when RW writes v1, so WR reads it one step later. At the
    // start WR finds the node as created (0).
    EXPECT_EQ(backward[0], 0.0);
    for (std::size_t i = 1; i < t.size(); ++i) EXPECT_EQ(backward[i], t[i - 1]) << "t=" << t[i];
    // The node holds both values: v0 from WR, v1 from RW.
    const auto v0 = loggedSlot(s, "RW", "P2d", "v0");
    const auto v1 = loggedSlot(s, "RW", "P2d", "v1");
    EXPECT_EQ(v0.back(), sine.back());
    EXPECT_EQ(v1.back(), t.back());
}

TEST(Signal2DBidirectional, WriterEndRunsBeforeReaderEndInTheSameStep)
{
    // Clock -> WR.write; the reader added first. Sorted, RW reads the time of its own step.
    System s;
    add(s, "Signal2DReadWrite", "RW");
    add(s, "Signal2DWriteRead", "WR");
    add(s, "SignalTime", "Clock");
    connectOk(s, "Clock", "out", "WR", "write");
    connectOk(s, "RW", "P2d", "WR", "P2d");
    ASSERT_TRUE(run(s, 0, 0.05, 1e-3, 51));
    const auto& t = s.logTime();
    const auto read = valuesOf(s, "RW", "read");
    ASSERT_EQ(read.size(), t.size());
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(read[i], t[i]) << "t=" << t[i];
}

TEST(Signal2DBidirectional, IndependentDestinationDropsTheOrderingSoTheReaderLagsAStep)
{
    // The same model with sh2d = 1: no order between the pair, the model's order holds (RW
    // first), so RW reads what WR wrote the step before.
    System s;
    add(s, "Signal2DReadWrite", "RW");
    add(s, "Signal2DWriteRead", "WR");
    add(s, "SignalTime", "Clock");
    setParam(s, "RW", "sh2d", "1");
    connectOk(s, "Clock", "out", "WR", "write");
    connectOk(s, "RW", "P2d", "WR", "P2d");
    ASSERT_TRUE(run(s, 0, 0.05, 1e-3, 51));
    const auto& t = s.logTime();
    const auto read = valuesOf(s, "RW", "read");
    ASSERT_EQ(read.size(), t.size());
    for (std::size_t i = 1; i < t.size(); ++i) EXPECT_EQ(read[i], t[i - 1]) << "t=" << t[i];
}

TEST(Signal2DBidirectional, LoopThroughThePairIsAnAlgebraicLoopWithDestination)
{
    System s;
    buildLoop(s, "0");
    Result<Simulation> sim = compile(s, {.startTime = 0.0, .stopTime = 0.01, .timestep = 1e-3, .logSamples = 11});
    ASSERT_TRUE(isOk(sim.status()));
    EXPECT_EQ(sim->initialise().code(), StatusCode::AlgebraicLoop);
}

TEST(Signal2DBidirectional, IndependentDestinationBreaksTheLoop)
{
    System s;
    buildLoop(s, "1");
    ASSERT_TRUE(run(s, 0, 0.01, 1e-3, 11));
    const auto sum = valuesOf(s, "Add", "out");
    const auto read = valuesOf(s, "RW", "read");
    ASSERT_EQ(sum.size(), 11u);
    // Order RW, Add, WR: RW reads last step's sum, so the sum counts the steps.
    for (std::size_t i = 1; i < sum.size(); ++i) {
        EXPECT_EQ(read[i], sum[i - 1]) << i;
        EXPECT_EQ(sum[i], sum[i - 1] + 1.0) << i;
    }
}

TEST(Signal2DBidirectional, Sh2dFollowsASystemParameterChangedBetweenRuns)
{
    // The sort comes before the parameters of a start are evaluated; sh2d given by a
    // system parameter must still sort by that parameter's current value.
    System s;
    ASSERT_TRUE(isOk(s.setSystemParameter("mode", "1", "integer", "", "", false)));
    buildLoop(s, "mode");
    Result<Simulation> sim = compile(s, {.startTime = 0.0, .stopTime = 0.01, .timestep = 1e-3, .logSamples = 11});
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->run()));
    ASSERT_TRUE(isOk(sim->reset()));
    ASSERT_TRUE(isOk(sim->setParameter("mode", "0")));
    EXPECT_EQ(sim->initialise().code(), StatusCode::AlgebraicLoop);
}

TEST(Signal2DBidirectional, Sh2dCountsInsideASubsystem)
{
    // The option is read before sorting by every component, subsystems' included.
    System root;
    auto owned = std::make_unique<System>();
    owned->setNameRaw("Sub");
    System& sub = *owned;
    root.addComponent(std::move(owned));
    buildLoop(sub, "1");
    ASSERT_TRUE(run(root, 0, 0.01, 1e-3, 11));
    EXPECT_EQ(sub.component("Add")->port("out")->node()->value(0),
              sub.component("RW")->port("read")->node()->value(0) + 1.0);
}

TEST(Signal2DBidirectional, ReadWriteInputNeverOrdersIt)
{
    // RW.read -> Gain -> RW.write closes a path through RW alone; its input "write" is an
    // independent destination, so this is no algebraic loop.
    System s;
    add(s, "Signal2DReadWrite", "RW");
    add(s, "SignalGain", "Gain");
    connectOk(s, "RW", "read", "Gain", "in");
    connectOk(s, "Gain", "out", "RW", "write");
    ASSERT_TRUE(run(s, 0, 0.01, 1e-3, 11));
    EXPECT_TRUE(allFinite(valuesOf(s, "RW", "read")));
}

TEST(Signal2DBidirectional, SplitFeedsP2dFromScalarWriters)
{
    // Clock -> Split.v1, Sine -> Split.v2: both scalar sides are written, so Split fills
    // v0 and v1 of the 2D node, which Signal2DRead unpacks. Split has no sort hints: the
    // model lists it between writers and reader, so the values are this step's.
    System s;
    add(s, "SignalTime", "Clock");
    add(s, "SignalSineWave", "Sine");
    add(s, "Signal2DSplit", "Split");
    add(s, "Signal2DRead", "Read");
    connectOk(s, "Clock", "out", "Split", "v1");
    connectOk(s, "Sine", "out", "Split", "v2");
    connectOk(s, "Split", "P2d", "Read", "P2d");
    ASSERT_TRUE(run(s, 0, 0.05, 1e-3, 51));
    const auto& t = s.logTime();
    const auto sine = valuesOf(s, "Sine", "out");
    const auto out1 = valuesOf(s, "Read", "out1");
    const auto out2 = valuesOf(s, "Read", "out2");
    ASSERT_EQ(out1.size(), t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_EQ(out1[i], t[i]) << "t=" << t[i];
        EXPECT_EQ(out2[i], sine[i]) << "t=" << t[i];
    }
}

TEST(Signal2DBidirectional, SplitFeedsScalarReadersFromP2d)
{
    // Signal2DWrite -> Split.P2d; Split.v1 -> Gain, Split.v2 -> Scope: neither scalar side
    // is a writer, so Split copies v0 and v1 out.
    System s;
    add(s, "SignalTime", "Clock");
    add(s, "Signal2DWrite", "Write");
    add(s, "Signal2DSplit", "Split");
    add(s, "SignalGain", "Gain");
    add(s, "SignalSink", "Scope");
    setParam(s, "Write", "in2#Value", "-3.75");
    connectOk(s, "Clock", "out", "Write", "in1");
    connectOk(s, "Write", "P2d", "Split", "P2d");
    connectOk(s, "Split", "v1", "Gain", "in");
    connectOk(s, "Split", "v2", "Scope", "in");
    ASSERT_TRUE(run(s, 0, 0.05, 1e-3, 51));
    const auto& t = s.logTime();
    const auto v1 = valuesOf(s, "Split", "v1");
    const auto v2 = valuesOf(s, "Split", "v2");
    const auto gain = valuesOf(s, "Gain", "out");
    ASSERT_EQ(v1.size(), t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_EQ(v1[i], t[i]) << "t=" << t[i];
        EXPECT_EQ(v2[i], -3.75) << "t=" << t[i];
        EXPECT_EQ(gain[i], t[i]) << "t=" << t[i];   // k = 1
    }
}

TEST(Signal2DBidirectional, SplitMixesDirectionsPerDimension)
{
    // v1 written by a constant (into v0), v2 read by a gain (from v1); the 2D side is a
    // Signal2DReadWrite, which reads v0 and writes v1.
    System s;
    add(s, "SignalConstant", "C");
    add(s, "Signal2DReadWrite", "RW");
    add(s, "Signal2DSplit", "Split");
    add(s, "SignalGain", "Gain");
    setParam(s, "C", "y#Value", "3.5");
    setParam(s, "RW", "write#Value", "7.25");
    connectOk(s, "C", "y", "Split", "v1");
    connectOk(s, "Split", "v2", "Gain", "in");
    connectOk(s, "Split", "P2d", "RW", "P2d");
    ASSERT_TRUE(run(s, 0, 0.01, 1e-3, 11));
    EXPECT_EQ(valuesOf(s, "RW", "read").back(), 3.5);
    EXPECT_EQ(valuesOf(s, "Gain", "out").back(), 7.25);
}

TEST(Signal2DBidirectional, BidirectionalPortsConnectToReadAndWritePortsOfTheirNodeType)
{
    // Hopsan's connection check counts no bidirectional port: with the same node type it
    // joins another bidirectional port, a read port or a write port alike.
    System s;
    add(s, "Signal2DWriteRead", "WR");
    add(s, "Signal2DReadWrite", "RW");
    add(s, "Signal2DRead", "Read");
    add(s, "Signal2DWrite", "Write");
    add(s, "Signal2DSplit", "Split");
    EXPECT_TRUE(isOk(s.connect("WR", "P2d", "RW", "P2d")));
    EXPECT_TRUE(isOk(s.connect("RW", "P2d", "Read", "P2d")));
    EXPECT_TRUE(isOk(s.connect("Write", "P2d", "Split", "P2d")));
}

TEST(Signal2DBidirectional, BidirectionalPortOfAnotherNodeTypeIsRefused)
{
    System s;
    add(s, "Signal2DWriteRead", "WR");
    add(s, "Signal2DSplit", "Split");
    add(s, "SignalGain", "Gain");
    add(s, "HydraulicVolume", "V");
    // A 2D port on a scalar signal input, and the other way round.
    const Status toScalar = s.connect("WR", "P2d", "Gain", "in");
    EXPECT_EQ(toScalar.code(), StatusCode::IllegalConnection);
    EXPECT_NE(toScalar.message().find("node types differ (NodeSignal2D vs NodeSignal)"), std::string::npos)
        << toScalar.message();
    EXPECT_EQ(s.connect("Split", "v1", "WR", "P2d").code(), StatusCode::IllegalConnection);
    // A scalar bidirectional port on a hydraulic node.
    const Status toPower = s.connect("Split", "v1", "V", "P1");
    EXPECT_EQ(toPower.code(), StatusCode::IllegalConnection);
    EXPECT_NE(toPower.message().find("node types differ"), std::string::npos) << toPower.message();
    // Nothing was connected.
    EXPECT_FALSE(s.component("WR")->port("P2d")->isConnected());
    EXPECT_FALSE(s.component("Split")->port("v1")->isConnected());
}

TEST(Signal2DBidirectional, SecondWriterOnASplitScalarNodeIsRefused)
{
    // A bidirectional port does not count as a writer, but the one-writer rule still holds
    // for the write ports on its node.
    System s;
    add(s, "Signal2DSplit", "Split");
    add(s, "SignalConstant", "C1");
    add(s, "SignalConstant", "C2");
    connectOk(s, "C1", "y", "Split", "v1");
    const Status refused = s.connect("C2", "y", "Split", "v1");
    EXPECT_EQ(refused.code(), StatusCode::IllegalConnection);
    EXPECT_NE(refused.message().find("only one write port"), std::string::npos) << refused.message();
}

TEST(Signal2DBidirectional, EachTypeRunsAloneToItsStopTime)
{
    for (const char* type : {"Signal2DWriteRead", "Signal2DReadWrite", "Signal2DSplit"}) {
        System s;
        add(s, type, "X");
        ASSERT_TRUE(run(s, 0, 0.1, 1e-3, 11)) << type;
        EXPECT_NEAR(s.logTime().back(), 0.1, 1e-12) << type;
        for (const auto& [name, port] : s.component("X")->portsByName()) {
            if (port->kind() == PortKind::Read) continue;   // a lone input's node is not logged
            const auto& vars = nodeTypeInfo(port->nodeType()).variables;
            for (const auto& v : vars)
                EXPECT_TRUE(allFinite(loggedSlot(s, "X", name, std::string(v.name)))) << type << "." << name;
        }
    }
}

TEST(Signal2DBidirectional, HmfRoundTripKeepsTheConnectionsAndSh2d)
{
    System s;
    s.setNameRaw("Pair");
    buildPair(s);
    add(s, "Signal2DSplit", "Split");
    add(s, "SignalGain", "Gain");
    connectOk(s, "Split", "P2d", "WR", "P2d");
    connectOk(s, "Split", "v1", "Gain", "in");
    setParam(s, "RW", "sh2d", "1");
    const std::string saved = saveHmfString(s);
    LoadedModel loaded = loadHmfString(saved, ".", "saved pair");
    ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
    EXPECT_EQ(saveHmfString(*loaded.root), saved);
    System& copy = *loaded.root;
    EXPECT_EQ(copy.component("RW")->parameters().find("sh2d")->value, "1");
    EXPECT_TRUE(copy.component("RW")->port("P2d")->isConnected());
    EXPECT_EQ(copy.component("Split")->port("P2d")->node(), copy.component("WR")->port("P2d")->node());
    // Both simulate alike, bit for bit.
    const std::optional<Simulation> first = runToStop(compile(s, {.stopTime = 0.1, .timestep = 1e-3, .logSamples = 101}));
    const std::optional<Simulation> second =
        runToStop(compile(copy, {.stopTime = 0.1, .timestep = 1e-3, .logSamples = 101}));
    ASSERT_TRUE(first && second);
    EXPECT_EQ(loggedColumns(first->results()), loggedColumns(second->results()));
}
