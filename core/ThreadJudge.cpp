#include "core/ThreadJudge.h"

namespace tlmhub {

bool ThreadJudge::keepThreads(std::size_t takenSteps, double seconds)
{
    if (!mPeriodStarted) {
        mPeriodStarted = true;
        mPeriodStart = seconds;
        mPeriodStartStep = takenSteps;
        return true;
    }
    const double elapsed = seconds - mPeriodStart;
    if (elapsed < kPeriodSeconds) return true;
    const double perStep = elapsed / static_cast<double>(takenSteps - mPeriodStartStep);
    mPeriodStart = seconds;
    mPeriodStartStep = takenSteps;
    const bool slow = !(perStep < kSpeedMargin * mSingleThreadedStepSeconds);
    const bool secondSlowInARow = slow && mLastPeriodSlow;
    mLastPeriodSlow = slow;
    return !secondSlowInARow;
}

} // namespace tlmhub
