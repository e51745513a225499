#include <gtest/gtest.h>

#include "core/numerics/Delay.h"

using namespace tlmhub;

TEST(Delay, ReturnsInitForNCallsThenTheInputs)
{
    Delay d;
    d.initialize(3, 7.0);
    EXPECT_EQ(d.getSize(), 3u);
    EXPECT_EQ(d.update(1.0), 7.0);
    EXPECT_EQ(d.update(2.0), 7.0);
    EXPECT_EQ(d.update(3.0), 7.0);
    EXPECT_EQ(d.update(4.0), 1.0);
    EXPECT_EQ(d.update(5.0), 2.0);
    EXPECT_EQ(d.update(6.0), 3.0);
}

TEST(Delay, Accessors)
{
    Delay d;
    d.initialize(4, 0.0);
    for (double v : {1.0, 2.0, 3.0, 4.0, 5.0}) { d.update(v); }
    // Buffer now holds 2,3,4,5 (oldest..newest).
    EXPECT_EQ(d.getOldest(), 2.0);
    EXPECT_EQ(d.getNewest(), 5.0);
    EXPECT_EQ(d.getIdx(0), 5.0);
    EXPECT_EQ(d.getIdx(1), 4.0);
    EXPECT_EQ(d.getIdx(3), 2.0);
    EXPECT_EQ(d.getIdx(4), 5.0); // wraps
    EXPECT_EQ(d.getOldIdx(0), 2.0);
    EXPECT_EQ(d.getOldIdx(2), 4.0);
    EXPECT_EQ(d.getOldIdx(5), 3.0); // wraps
    // getOldest is what the next update returns.
    const double expected = d.getOldest();
    EXPECT_EQ(d.update(6.0), expected);
}

TEST(Delay, ZeroOrNegativeStepsGiveOneStepDelay)
{
    Delay d;
    d.initialize(0, -1.0);
    EXPECT_EQ(d.getSize(), 1u);
    EXPECT_EQ(d.update(10.0), -1.0);
    EXPECT_EQ(d.update(20.0), 10.0);
    d.initialize(-5, 3.0);
    EXPECT_EQ(d.getSize(), 1u);
    EXPECT_EQ(d.update(1.0), 3.0); // re-initialise discards content
}

TEST(Delay, TimeFormRoundsHalfUp)
{
    Delay d;
    d.initialize(0.625, 0.25, 0.0); // 2.5 steps -> 3
    EXPECT_EQ(d.getSize(), 3u);
    d.initialize(0.5, 0.25, 0.0); // 2.0 -> 2
    EXPECT_EQ(d.getSize(), 2u);
    d.initialize(0.5625, 0.25, 0.0); // 2.25 -> 2
    EXPECT_EQ(d.getSize(), 2u);
    // TLM line with T == Ts: T - Ts rounds to 0 and is clamped to 1.
    const double Ts = 0.001;
    d.initialize(Ts - Ts, Ts, 0.0);
    EXPECT_EQ(d.getSize(), 1u);
}

TEST(Delay, TemplateWorksForOtherTypes)
{
    DelayT<int> d;
    d.initialize(2, 9);
    EXPECT_EQ(d.update(1), 9);
    EXPECT_EQ(d.update(2), 9);
    EXPECT_EQ(d.update(3), 1);
}
