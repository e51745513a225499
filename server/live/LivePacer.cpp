#include "server/live/LivePacer.h"

#include <cmath>

namespace tlmhub::server {

namespace {

double pacerSeconds(LivePacer::Clock::duration d)
{
    return std::chrono::duration<double>(d).count();
}

} // namespace

LivePacer::LivePacer(double timestep, std::optional<double> speed, Clock::time_point now, bool paused)
    : mTimestep(timestep), mSpeed(speed), mPaused(paused)
{
    anchor(now);
}

void LivePacer::anchor(Clock::time_point now)
{
    mAnchorTime = now;
    mAnchorSteps = mTaken;
    mWindowTime = now;
    mWindowSteps = mTaken;
}

std::uint64_t LivePacer::due(Clock::time_point now, std::uint64_t maxSlice)
{
    if (mPaused) return 0;
    if (!mSpeed) return maxSlice;
    const auto stepsBy = [&](Clock::time_point t) {
        // The small tolerance keeps a step whose time is exactly now from rounding away.
        return mAnchorSteps + static_cast<std::uint64_t>(std::floor(pacerSeconds(t - mAnchorTime) * *mSpeed / mTimestep + 1e-9));
    };
    if (now - mAnchorTime > kMaxBacklog && stepsBy(now - kMaxBacklog) > mTaken) {
        // Too far behind: pace from here (the window's measure reports the shortfall).
        mAnchorTime = now;
        mAnchorSteps = mTaken;
        return 0;
    }
    const std::uint64_t target = stepsBy(now);
    return target > mTaken ? std::min(target - mTaken, maxSlice) : 0;
}

void LivePacer::pause(Clock::time_point)
{
    mPaused = true;
    mAchieved = 0.0;
}

void LivePacer::resume(Clock::time_point now)
{
    if (!mPaused) return;
    mPaused = false;
    anchor(now);
}

void LivePacer::setSpeed(std::optional<double> speed, Clock::time_point now)
{
    mSpeed = speed;
    anchor(now);
}

std::optional<double> LivePacer::measure(Clock::time_point now)
{
    if (mPaused || now - mWindowTime < kWindow) return std::nullopt;
    mAchieved = static_cast<double>(mTaken - mWindowSteps) * mTimestep / pacerSeconds(now - mWindowTime);
    mWindowTime = now;
    mWindowSteps = mTaken;
    return mAchieved;
}

} // namespace tlmhub::server
