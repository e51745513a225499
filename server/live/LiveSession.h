#pragma once
// One live session: a compiled simulation stepped in time with the wall clock (LivePacer) by
// ticks of a steady_timer on a strand of its own, so it holds no thread between ticks. Each
// tick applies the values live.set asked for, runs the steps due (within a time budget, so
// one session cannot hog a thread; the rest follows at once on a new tick), and at the
// display rate sends the streamed variables' current values as an event.live.frame.
// Control (set, pause, speed, ...) comes from the owner's connection on other threads: the
// session's state is guarded by a mutex, held by a tick only for one budget.
#include "server/jobs/Job.h"
#include "server/jobs/StreamFrame.h"
#include "server/live/LivePacer.h"
#include "server/protocol/Messages.generated.h"

#include "core/ResultTable.h"
#include "core/Results.h"
#include "core/Simulation.h"

#include <boost/asio/any_io_executor.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>

#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tlmhub::server {

struct LiveSessionConfig {
    std::uint64_t id = 0;
    std::int64_t ownerId = 0;
    std::optional<double> speed = 1.0;   // none: "max"
    bool paused = false;
    double rate = 30.0;                  // frames per second
    std::chrono::milliseconds idleTimeout{600'000};
    // Samples (and changes) a session records for live.record: the job log limit, or fewer
    // when that many samples of its variables would pass the job result limit; `recordLimit`
    // names the limit that holds, for the message when the recording stops.
    std::size_t maxRecordedSamples = 100'000;
    std::string recordLimit = "--max-log-samples";
    // The job its model was compiled as, and its resolved start, step and stop: what live.record
    // stores its run as.
    JobRequest job;
    JobInfo resolved;
    // The model is an assignment's copy: each live.set asks the lab's lock
    // (server/labs/LiveLabAccess.h).
    bool labCopy = false;
    // Pacing reads this clock (tests inject one); the timer waits in real time.
    std::function<LivePacer::Clock::time_point()> clock;
};

// Where a session's output goes: the owner's connection. Called on the session's strand.
struct LiveSessionSink {
    // False once the connection gave the stream up (too slow): the session ends.
    std::function<bool(StreamFrame)> frame;
    std::function<void(std::string)> event;
};

// A streamed variable: its name and where its current value lies.
struct LiveVariable {
    std::string name;
    VariableRef ref;
};

// A value live.set changed: applied after the step at model time `time`.
struct LiveChange {
    double time = 0.0;
    std::string name;
    double value = 0.0;
};

// What a session has run so far (live.record): every frame's sample since its start, up to
// LiveSessionConfig::maxRecordedSamples, and every change applied.
struct LiveRecording {
    ResultTable samples;
    std::vector<LiveChange> changes;
    std::uint64_t steps = 0;   // taken since the start
    bool full = false;         // the limit stopped the recording
};

class LiveSession : public std::enable_shared_from_this<LiveSession> {
public:
    // Per name, live.set values are applied at most this often (the last one wins).
    static constexpr std::chrono::milliseconds kSetInterval{10};
    // Steps one tick runs before it lets other sessions have the thread.
    static constexpr std::chrono::milliseconds kTickBudget{10};
    static constexpr std::uint64_t kMaxStepRequest = 1'000'000;
    // The samples kept for a socket that starts watching late (live.subscribe): this much
    // wall time of frames, at most kKeptFrames (60 s at the highest frame rate).
    static constexpr std::chrono::seconds kKeptTime{60};
    static constexpr std::size_t kKeptFrames = 60 * 120;

    // A reply: the state after the request, or a protocol error code and message.
    struct Reply {
        std::string code;   // empty: done
        std::string message;
        protocol::LiveStateData state;
        bool ok() const { return code.empty(); }
    };

    // `ended` is called once, on any thread, when the session has stopped.
    LiveSession(boost::asio::any_io_executor executor, LiveSessionConfig config, Simulation simulation,
                std::vector<LiveVariable> variables, LiveSessionSink sink, std::function<void(std::uint64_t)> ended);

    std::uint64_t id() const { return mConfig.id; }
    std::int64_t ownerId() const { return mConfig.ownerId; }
    const LiveSessionConfig& config() const { return mConfig; }
    // What live.set may change, with the values the run starts from (as live.start replies).
    const std::vector<LiveValue>& liveValues() const { return mLiveValues; }
    // The streamed variables' names, in the order frames carry them.
    std::vector<std::string> variableNames() const;

    // Starts the ticks (the registry, once the session is in it): until start(), they only
    // watch the idle timeout, so a session whose connection ended before its reply ends too.
    void arm();
    // Sends the first state event and frame and starts the run (after live.start's reply).
    void start();
    Reply set(const std::string& name, double value);
    Reply pause();
    Reply resume();
    Reply setSpeed(std::optional<double> speed);
    Reply step(std::uint64_t steps);
    // Ends the session; `reason` goes in its last event.live.state (none: no event, the
    // connection is gone).
    Reply stop(const std::optional<std::string>& reason);
    // A message from the owner: the idle timeout starts again.
    void touch();
    // Another socket watches the session (the owner's, or through `throughClass`, a class it
    // is shared with: 0 for the owner's): its first frame carries the kept samples, then it
    // gets every frame and state event. Returns the watch's id for unwatch, 0 once stopped.
    std::uint64_t watch(LiveSessionSink sink, std::int64_t throughClass = 0);
    void unwatch(std::uint64_t watchId);
    // Shared with a class (docs/live-sessions.md, "In a lab"): its members may watch. Who may
    // share and watch is the caller's to decide (server/labs/LiveLabAccess.h).
    void share(std::int64_t classId);
    // Ends the watches through `classId`: each gets event.live.state stopped, reason unshared.
    void unshare(std::int64_t classId);
    std::vector<std::int64_t> sharedClasses() const;
    Reply state() const;
    // A copy of the samples and changes recorded since the start.
    LiveRecording recording() const;

private:
    // Keeps a frame's sample for live.record, within the limit.
    void record(const FrameSamples& samples);
    void scheduleTick(bool now);
    void tick(bool onTimer);
    // The rest run with mMutex held.
    void applyDueSets(LivePacer::Clock::time_point now);
    // Runs up to `steps` steps within kTickBudget; the steps run.
    std::uint64_t runSteps(std::uint64_t steps, LivePacer::Clock::time_point start);
    void sendFrame(LivePacer::Clock::time_point now);
    void sendState(const std::optional<std::string>& reason = {}, const std::string& message = {},
                   bool toOwner = true);
    protocol::LiveStateData stateData() const;
    Reply stateReply() const { return {.code = {}, .message = {}, .state = stateData()}; }
    void end(const std::optional<std::string>& reason, const std::string& message = {});

    LiveSessionConfig mConfig;
    boost::asio::strand<boost::asio::any_io_executor> mStrand;
    boost::asio::steady_timer mTimer;
    std::chrono::steady_clock::time_point mNextTick;   // real time, for the timer
    const std::chrono::steady_clock::duration mFramePeriod;

    mutable std::mutex mMutex;
    Simulation mSimulation;
    std::vector<LiveVariable> mVariables;
    std::shared_ptr<const FrameLayout> mLayout;
    LiveSessionSink mSink;
    std::function<void(std::uint64_t)> mEnded;
    std::vector<LiveValue> mLiveValues;
    std::set<std::string> mLivePaths;
    LivePacer mPacer;
    LivePacer::Clock::time_point mStartedAt, mLastTouch, mLastFrame;
    std::uint64_t mStepsRequested = 0;   // by live.step while paused
    bool mLagging = false;               // last window's achieved speed was short of the speed
    bool mStarted = false;
    bool mStopped = false;
    std::map<std::string, double> mPendingSets;
    std::deque<std::pair<LivePacer::Clock::time_point, std::shared_ptr<const FrameSamples>>> mKept;
    struct Watcher {
        LiveSessionSink sink;
        std::int64_t throughClass = 0;   // 0: the owner's own socket
    };
    std::map<std::uint64_t, Watcher> mWatchers;
    std::set<std::int64_t> mSharedClasses;
    std::uint64_t mNextWatch = 1;
    std::map<std::string, LivePacer::Clock::time_point> mLastSetApplied;
    LiveRecording mRecording;
};

} // namespace tlmhub::server
