#pragma once
// The judge of an automatic thread count (System::simulateStepsAutoThreaded): a run keeps its
// threads only while they are measured to be clearly faster than one thread. It is asked
// throughout the run, not once: when other processes take a core later, a thread of the
// group waits for its core at every phase barrier and the threads soon lose to one thread.
//
// Threaded steps are judged by their mean time per step over periods of at least
// kPeriodSeconds, against the single-threaded time per step measured before the threads
// started; two periods in a row that were not faster end them. A short process taking a
// core for a time slice or two slows one period at most (judged on single 10 ms periods,
// x200 runs on a lightly loaded machine often lost their threads that way); a lost core
// slows every period, and two of them are short next to what it would cost.
#include <cstddef>

namespace tlmhub {

class ThreadJudge {
public:
    // Threads must take under this share of the single-threaded time.
    static constexpr double kSpeedMargin = 0.93;
    static constexpr double kPeriodSeconds = 50e-3;

    explicit ThreadJudge(double singleThreadedStepSeconds) : mSingleThreadedStepSeconds(singleThreadedStepSeconds) {}

    // Called at the end of every timed window of threaded steps with the steps the run has
    // taken and the time in seconds (from any fixed origin). False at the end of the second
    // period in a row that was not faster: the threads end there.
    bool keepThreads(std::size_t takenSteps, double seconds);

private:
    double mSingleThreadedStepSeconds;
    bool mPeriodStarted = false;
    bool mLastPeriodSlow = false;
    std::size_t mPeriodStartStep = 0;
    double mPeriodStart = 0.0;
};

} // namespace tlmhub
