#pragma once
// How many steps a live session owes the wall clock: model time follows wall time × speed
// from an anchor (set at the start, at a resume and at a change of speed), and the speed it
// actually achieves is measured over windows of a second. Pure arithmetic on the times it is
// given, so tests drive it with a clock of their own.
#include <chrono>
#include <cstdint>
#include <optional>

namespace tlmhub::server {

class LivePacer {
public:
    using Clock = std::chrono::steady_clock;
    // A session that falls further behind than this stops trying to catch up: it goes on
    // from where it is, reporting the lower achieved speed, instead of racing in a burst.
    static constexpr std::chrono::milliseconds kMaxBacklog{1000};
    static constexpr std::chrono::milliseconds kWindow{1000};

    // `speed`: model seconds per wall second; none: as fast as possible ("max").
    LivePacer(double timestep, std::optional<double> speed, Clock::time_point now, bool paused);

    // Steps due by `now` that are not taken yet (0 while paused; at max, `maxSlice`).
    std::uint64_t due(Clock::time_point now, std::uint64_t maxSlice);
    void taken(std::uint64_t steps) { mTaken += steps; }
    std::uint64_t takenSteps() const { return mTaken; }

    void pause(Clock::time_point now);
    void resume(Clock::time_point now);
    void setSpeed(std::optional<double> speed, Clock::time_point now);
    bool paused() const { return mPaused; }
    std::optional<double> speed() const { return mSpeed; }

    // Once a window of kWindow has passed while running: the speed achieved over it (model
    // seconds per wall second), and a new window starts.
    std::optional<double> measure(Clock::time_point now);
    // The last measured speed (0 before the first window, and while paused).
    double achieved() const { return mAchieved; }

private:
    void anchor(Clock::time_point now);

    double mTimestep;
    std::optional<double> mSpeed;
    bool mPaused;
    std::uint64_t mTaken = 0;
    Clock::time_point mAnchorTime;
    std::uint64_t mAnchorSteps = 0;
    Clock::time_point mWindowTime;
    std::uint64_t mWindowSteps = 0;
    double mAchieved = 0.0;
};

} // namespace tlmhub::server
