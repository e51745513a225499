// Log sample selection (core.md §4.2) against the documented examples.
#include "TestHelpers.h"

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

System& simpleModel(System& s)
{
    add(s, "SignalConstant", "C");
    add(s, "SignalSink", "Sink");
    connectOk(s, "C", "y", "Sink", "in");
    return s;
}

} // namespace

TEST(LogSchedule, SubSystemExampleTimes)
{
    System s;
    simpleModel(s);
    ASSERT_TRUE(run(s, 0.0, 10.0, 0.001, 2048));
    const auto& t = s.logTime();
    ASSERT_EQ(s.numLoggedSamples(), 2048u);
    // Documented steps 0, 5, 10, 15, 20, 24, 29 ... 10000.
    const int steps[] = {0, 5, 10, 15, 20, 24, 29};
    for (int i = 0; i < 7; ++i) EXPECT_NEAR(t[i], steps[i] * 0.001, 1e-12) << i;
    EXPECT_NEAR(t.back(), 10.0, 1e-9);
}

TEST(LogSchedule, EveryStepWhenSamplesEqualStepsPlusOne)
{
    System s;
    simpleModel(s);
    ASSERT_TRUE(run(s, 0.0, 0.2, 0.001, 201));
    ASSERT_EQ(s.numLoggedSamples(), 201u);
    for (std::size_t i = 0; i < 201; ++i) EXPECT_NEAR(s.logTime()[i], i * 0.001, 1e-12);
}

TEST(LogSchedule, TooManySamplesAreLimitedToTheSteps)
{
    System s;
    simpleModel(s);
    ASSERT_TRUE(run(s, 0.0, 0.01, 0.001, 5000));
    EXPECT_EQ(s.numLoggedSamples(), 11u);
}

TEST(LogSchedule, LogStartTimeSkipsThePreRun)
{
    System s;
    simpleModel(s);
    s.logStartTime = 0.0;
    ASSERT_TRUE(run(s, -1.0, 10.0, 0.001, 2048));
    EXPECT_EQ(s.numLoggedSamples(), 2048u);
    EXPECT_NEAR(s.logTime().front(), 0.0, 1e-12);
    EXPECT_NEAR(s.logTime().back(), 10.0, 1e-9);
}

TEST(LogSchedule, OneSampleStoresTheInitialState)
{
    System s;
    simpleModel(s);
    ASSERT_TRUE(run(s, 0.0, 1.0, 0.001, 1));
    ASSERT_EQ(s.numLoggedSamples(), 1u);
    EXPECT_EQ(s.logTime()[0], 0.0);
}

TEST(LogSchedule, ZeroSamplesDisablesLogging)
{
    System s;
    simpleModel(s);
    ASSERT_TRUE(run(s, 0.0, 1.0, 0.001, 0));
    EXPECT_EQ(s.numLoggedSamples(), 0u);
    EXPECT_TRUE(s.logTime().empty());
}
