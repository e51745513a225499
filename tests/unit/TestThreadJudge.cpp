// The automatic thread count's judge, fed made-up times: threads stay while they are clearly
// faster than one thread and end once a period is not, also long after the start.
#include "core/ThreadJudge.h"

#include <gtest/gtest.h>

using namespace tlmhub;

namespace {

constexpr double kSingle = 100e-6;   // single-threaded seconds per step
constexpr std::size_t kWindow = 10;

// Asks the judge after each window of kWindow steps at `perStep` seconds, for `seconds`;
// false from its first no.
struct TimedRun {
    ThreadJudge judge{kSingle};
    std::size_t steps = 0;
    double now = 0.0;

    bool run(double perStep, double seconds)
    {
        for (const double end = now + seconds; now < end;) {
            steps += kWindow;
            now += perStep * kWindow;
            if (!judge.keepThreads(steps, now)) return false;
        }
        return true;
    }
};

} // namespace

TEST(ThreadJudge, ThreadsThatStayFasterAreKept)
{
    TimedRun threads;
    EXPECT_TRUE(threads.run(0.6 * kSingle, 5.0));
}

TEST(ThreadJudge, ThreadsNotClearlyFasterEndAfterTwoPeriods)
{
    TimedRun threads;
    EXPECT_FALSE(threads.run(0.95 * kSingle, 3 * ThreadJudge::kPeriodSeconds));
}

// The stale choice: threads that paid off at first, until another process took a core.
TEST(ThreadJudge, ThreadsEndWithinThreePeriodsOnceTheyStopPayingOff)
{
    TimedRun threads;
    ASSERT_TRUE(threads.run(0.6 * kSingle, 3.0));
    const double slowFrom = threads.now;
    EXPECT_FALSE(threads.run(20 * kSingle, 10.0));
    EXPECT_LE(threads.now - slowFrom, 3 * ThreadJudge::kPeriodSeconds + 20 * kSingle * kWindow);
}

// Something slowed one period a lot (a burst of other work); the next one is fast again.
TEST(ThreadJudge, OneSlowPeriodBetweenFastOnesDoesNotEndThem)
{
    TimedRun threads;
    ASSERT_TRUE(threads.run(0.6 * kSingle, 0.5));
    ASSERT_TRUE(threads.run(2 * kSingle, ThreadJudge::kPeriodSeconds));
    EXPECT_TRUE(threads.run(0.6 * kSingle, 0.5));
}

// A short process takes a core for a time slice; the period around it is still faster.
TEST(ThreadJudge, AStallOfATimeSliceDoesNotEndThem)
{
    TimedRun threads;
    ASSERT_TRUE(threads.run(0.6 * kSingle, 0.5));
    ASSERT_TRUE(threads.run(10e-3 / kWindow, 10e-3));
    EXPECT_TRUE(threads.run(0.6 * kSingle, 0.5));
}

TEST(ThreadJudge, NothingIsJudgedBeforeAPeriodHasPassed)
{
    constexpr double period = ThreadJudge::kPeriodSeconds;
    ThreadJudge judge(kSingle);
    EXPECT_TRUE(judge.keepThreads(100, 1.0));                    // starts the first period
    EXPECT_TRUE(judge.keepThreads(110, 1.0 + 0.9 * period));     // slow, but early
    EXPECT_TRUE(judge.keepThreads(120, 1.0 + period));           // the first slow period
    EXPECT_TRUE(judge.keepThreads(130, 1.0 + 1.9 * period));     // slow, but early
    EXPECT_FALSE(judge.keepThreads(140, 1.0 + 2 * period));      // the second in a row
}
