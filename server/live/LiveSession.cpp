#include "server/live/LiveSession.h"

#include "server/api/CoreErrorCodes.h"
#include "server/http/JsonText.h"

#include <boost/asio/bind_executor.hpp>
#include <boost/asio/post.hpp>

#include <algorithm>
#include <cmath>

namespace tlmhub::server {

namespace {

// Steps a tick may owe at "max": the time budget ends the tick long before.
constexpr std::uint64_t kLiveMaxSlice = 1'000'000'000;
// Below this share of the asked speed, the session says it cannot keep up.
constexpr double kLiveKeepingUp = 0.95;

nlohmann::json liveSpeedJson(const std::optional<double>& speed)
{
    return speed ? nlohmann::json(*speed) : nlohmann::json("max");
}

LiveSession::Reply liveRefusal(std::string code, std::string message)
{
    return {.code = std::move(code), .message = std::move(message), .state = {}};
}

} // namespace

LiveSession::LiveSession(boost::asio::any_io_executor executor, LiveSessionConfig config, Simulation simulation,
                         std::vector<LiveVariable> variables, LiveSessionSink sink,
                         std::function<void(std::uint64_t)> ended)
    : mConfig(std::move(config)), mStrand(boost::asio::make_strand(executor)), mTimer(mStrand),
      mFramePeriod(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(1.0 / mConfig.rate))),
      mSimulation(std::move(simulation)), mVariables(std::move(variables)), mSink(std::move(sink)),
      mEnded(std::move(ended)), mLiveValues(mSimulation.liveValues()),
      mPacer(mSimulation.timestep(), mConfig.speed, mConfig.clock(), mConfig.paused)
{
    std::vector<std::string> names;
    for (const LiveVariable& v : mVariables) names.push_back(v.name);
    mLayout = std::make_shared<const FrameLayout>(std::move(names));
    for (const LiveValue& v : mLiveValues) mLivePaths.insert(v.path);
    for (const LiveVariable& v : mVariables) mRecording.samples.columns.push_back({.name = v.name, .unit = {}, .data = {}});
    mStartedAt = mLastTouch = mConfig.clock();
}

std::vector<std::string> LiveSession::variableNames() const
{
    std::vector<std::string> names;
    for (const LiveVariable& v : mVariables) names.push_back(v.name);   // fixed from the start
    return names;
}

void LiveSession::arm()
{
    std::lock_guard lock(mMutex);
    // Ticks fall on a grid of the frame period counted from the clock's epoch, so sessions of
    // one rate tick together: the live thread wakes once for all of them, and their frames
    // leave in one burst (40 sessions at 30 frames a second: 30 wake-ups a second, not 1200).
    const auto period = mFramePeriod;
    mNextTick = std::chrono::steady_clock::time_point((std::chrono::steady_clock::now().time_since_epoch() / period) * period);
    scheduleTick(false);
}

void LiveSession::start()
{
    std::lock_guard lock(mMutex);
    if (mStopped) return;
    mStarted = true;
    mStartedAt = mLastTouch = mConfig.clock();
    mPacer = LivePacer(mSimulation.timestep(), mConfig.speed, mStartedAt, mConfig.paused);
    sendState();
    // The first frame shows where the run starts.
    sendFrame(mStartedAt);
}

void LiveSession::scheduleTick(bool now)
{
    // A tick that ran out of budget goes on at once, behind whatever else waits for the pool.
    if (now) return boost::asio::post(mStrand, [self = shared_from_this()] { self->tick(false); });
    // On the grid; a tick late by more than a period skips the instants already gone.
    const auto clockNow = std::chrono::steady_clock::now();
    mNextTick += mFramePeriod;
    if (mNextTick < clockNow) mNextTick += ((clockNow - mNextTick) / mFramePeriod + 1) * mFramePeriod;
    mTimer.expires_at(mNextTick);
    mTimer.async_wait(boost::asio::bind_executor(mStrand, [self = shared_from_this()](boost::system::error_code ec) {
        if (!ec) self->tick(true);
    }));
}

void LiveSession::tick(bool onTimer)
{
    std::unique_lock lock(mMutex);
    if (mStopped) return;
    const auto now = mConfig.clock();
    if (now - mLastTouch > mConfig.idleTimeout)
        return end("idle_timeout", "no message from the session's owner for " +
                                       std::to_string(mConfig.idleTimeout.count()) + " ms (--live-idle-timeout)");
    if (!mStarted) return scheduleTick(false);
    applyDueSets(now);
    const std::uint64_t due = mPacer.paused() ? mStepsRequested : mPacer.due(now, kLiveMaxSlice);
    const std::uint64_t ran = runSteps(due, now);
    if (mStopped) return;
    mPacer.taken(ran);
    const bool stepped = mPacer.paused() && mStepsRequested > 0;
    if (mPacer.paused()) mStepsRequested -= std::min(ran, mStepsRequested);
    const bool finished = mSimulation.state() == SimulationState::Finished;
    const auto after = mConfig.clock();
    // The timer ticks once per frame period: each of them that ran steps sends a frame. (Measured
    // from the last frame instead, a tick that came a little early after a late one sent none,
    // and 30 frames a second became about 19.) A tick that goes on at once after running out of
    // budget sends one only when a period has passed. A paused session sends nothing; the frame
    // of a live.step shows its last step at once.
    if ((ran > 0 && (onTimer || after - mLastFrame >= mFramePeriod)) || finished ||
        (stepped && mStepsRequested == 0))
        sendFrame(after);
    if (finished) return end("finished", "the model reached its stop time");
    if (const auto achieved = mPacer.measure(after); achieved && mPacer.speed()) {
        // Never drift silently: every window short of the speed is reported, and the recovery.
        const bool lagging = *achieved < kLiveKeepingUp * *mPacer.speed();
        if (lagging || mLagging) sendState();
        mLagging = lagging;
    }
    scheduleTick(ran < due);
}

void LiveSession::applyDueSets(LivePacer::Clock::time_point now)
{
    for (auto it = mPendingSets.begin(); it != mPendingSets.end();) {
        auto& last = mLastSetApplied[it->first];
        if (last != LivePacer::Clock::time_point{} && now - last < kSetInterval) {
            ++it;
            continue;
        }
        // Checked when it was asked for: a live path and a finite value.
        if (mSimulation.changeWhileRunning(it->first, it->second) &&
            mRecording.changes.size() < mConfig.maxRecordedSamples)
            mRecording.changes.push_back({.time = mSimulation.time(), .name = it->first, .value = it->second});
        last = now;
        it = mPendingSets.erase(it);
    }
}

std::uint64_t LiveSession::runSteps(std::uint64_t steps, LivePacer::Clock::time_point start)
{
    std::uint64_t ran = 0;
    std::uint64_t chunk = 64;
    while (ran < steps && mSimulation.state() != SimulationState::Finished) {
        const std::uint64_t n = std::min(chunk, steps - ran);
        const std::size_t before = mSimulation.takenSteps();
        if (const Status status = mSimulation.runSteps(n); !status) {
            end("failed", status.message());
            return ran;
        }
        ran += mSimulation.takenSteps() - before;
        if (mSimulation.takenSteps() == before) break;
        if (mConfig.clock() - start >= kTickBudget) break;
        chunk = std::min<std::uint64_t>(chunk * 2, 65536);
    }
    return ran;
}

void LiveSession::sendFrame(LivePacer::Clock::time_point now)
{
    mLastFrame = now;
    auto samples = std::make_shared<FrameSamples>();
    samples->time.push_back(mSimulation.time());
    for (const LiveVariable& v : mVariables) samples->columns.push_back({v.ref.port->node()->value(v.ref.slot)});
    mKept.emplace_back(now, samples);
    record(*samples);
    while (mKept.size() > kKeptFrames || now - mKept.front().first > kKeptTime) mKept.pop_front();
    // Every socket gets the same samples (encoded once for all of them).
    const auto frameOf = [&] {
        StreamFrame frame;
        frame.layout = mLayout;
        frame.parts.push_back(samples);
        frame.live = LiveFrameStamp{.sessionId = mConfig.id,
                                    .modelTime = mSimulation.time(),
                                    .wallTime = std::chrono::duration<double>(now - mStartedAt).count(),
                                    .speed = mPacer.speed()};
        return frame;
    };
    // A watcher too slow for its frames stops watching; the owner's ends the session.
    std::erase_if(mWatchers, [&](auto& watcher) { return !watcher.second.sink.frame(frameOf()); });
    if (!mSink.frame(frameOf())) end(std::nullopt);
}

protocol::LiveStateData LiveSession::stateData() const
{
    return {.state = mStopped ? "stopped" : mPacer.paused() ? "paused" : "running",
            .speed = liveSpeedJson(mPacer.speed()),
            .modelTime = mSimulation.time()};
}

void LiveSession::sendState(const std::optional<std::string>& reason, const std::string& message, bool toOwner)
{
    protocol::LiveStateData state = stateData();
    protocol::LiveStateEvent event{.sessionId = static_cast<std::int64_t>(mConfig.id),
                                   .state = state.state,
                                   .speed = state.speed,
                                   .achievedSpeed = mPacer.paused() ? 0.0 : mPacer.achieved(),
                                   .modelTime = state.modelTime,
                                   .reason = reason,
                                   .message = message.empty() ? std::nullopt : std::optional(message)};
    const std::string text = toJsonText(event);
    for (const auto& [id, watcher] : mWatchers) watcher.sink.event(text);
    if (toOwner) mSink.event(text);
}

void LiveSession::end(const std::optional<std::string>& reason, const std::string& message)
{
    if (mStopped) return;
    mStopped = true;
    // Without a reason the owner's socket is gone: only those watching are told.
    if (reason) sendState(reason, message);
    else sendState("closed", "the session's owner disconnected", false);
    mWatchers.clear();
    mSharedClasses.clear();
    boost::asio::post(mStrand, [self = shared_from_this()] { self->mTimer.cancel(); });
    mEnded(mConfig.id);
}

LiveSession::Reply LiveSession::set(const std::string& name, double value)
{
    std::lock_guard lock(mMutex);
    if (mStopped) return liveRefusal("not_found", "the live session has ended");
    if (!mLivePaths.count(name) || !std::isfinite(value)) {
        // The core says why (restart_required, unknown parameter, not finite); a refused
        // change leaves the run as it was.
        const Status refused = mSimulation.changeWhileRunning(name, value);
        if (!refused) return liveRefusal(protocolErrorCode(refused.code()), refused.message());
    }
    mPendingSets[name] = value;
    return stateReply();
}

LiveSession::Reply LiveSession::pause()
{
    std::lock_guard lock(mMutex);
    if (mStopped) return liveRefusal("not_found", "the live session has ended");
    if (!mPacer.paused()) {
        mPacer.pause(mConfig.clock());
        mLagging = false;
        sendState();
    }
    return stateReply();
}

LiveSession::Reply LiveSession::resume()
{
    std::lock_guard lock(mMutex);
    if (mStopped) return liveRefusal("not_found", "the live session has ended");
    if (mPacer.paused()) {
        mStepsRequested = 0;
        mPacer.resume(mConfig.clock());
        sendState();
    }
    return stateReply();
}

LiveSession::Reply LiveSession::setSpeed(std::optional<double> speed)
{
    std::lock_guard lock(mMutex);
    if (mStopped) return liveRefusal("not_found", "the live session has ended");
    mPacer.setSpeed(speed, mConfig.clock());
    mLagging = false;
    sendState();
    return stateReply();
}

LiveSession::Reply LiveSession::step(std::uint64_t steps)
{
    std::lock_guard lock(mMutex);
    if (mStopped) return liveRefusal("not_found", "the live session has ended");
    if (!mPacer.paused()) return liveRefusal("conflict", "live.step needs a paused session (live.pause)");
    if (mStepsRequested + steps > kMaxStepRequest)
        return liveRefusal("limit_exceeded", "at most " + std::to_string(kMaxStepRequest) + " steps may wait to be run");
    mStepsRequested += steps;
    return stateReply();
}

LiveSession::Reply LiveSession::stop(const std::optional<std::string>& reason)
{
    std::lock_guard lock(mMutex);
    end(reason);
    return stateReply();
}

std::uint64_t LiveSession::watch(LiveSessionSink sink, std::int64_t throughClass)
{
    std::lock_guard lock(mMutex);
    if (mStopped) return 0;
    if (!mKept.empty()) {
        // The kept samples as one frame, stamped as the latest.
        StreamFrame frame;
        frame.layout = mLayout;
        for (const auto& [at, samples] : mKept) frame.parts.push_back(samples);
        frame.live = LiveFrameStamp{.sessionId = mConfig.id,
                                    .modelTime = mKept.back().second->time.back(),
                                    .wallTime = std::chrono::duration<double>(mKept.back().first - mStartedAt).count(),
                                    .speed = mPacer.speed()};
        if (!sink.frame(std::move(frame))) return 0;
    }
    const std::uint64_t id = mNextWatch++;
    mWatchers.emplace(id, Watcher{std::move(sink), throughClass});
    return id;
}

void LiveSession::share(std::int64_t classId)
{
    std::lock_guard lock(mMutex);
    if (!mStopped) mSharedClasses.insert(classId);
}

void LiveSession::unshare(std::int64_t classId)
{
    std::lock_guard lock(mMutex);
    mSharedClasses.erase(classId);
    // The session goes on for everyone else: only these watchers are told it stopped for them.
    protocol::LiveStateData state = stateData();
    const std::string text = toJsonText(protocol::LiveStateEvent{
        .sessionId = static_cast<std::int64_t>(mConfig.id),
        .state = "stopped",
        .speed = state.speed,
        .achievedSpeed = 0.0,
        .modelTime = state.modelTime,
        .reason = std::string("unshared"),
        .message = std::string("the session's owner stopped sharing it with your class")});
    std::erase_if(mWatchers, [&](auto& watcher) {
        if (watcher.second.throughClass != classId) return false;
        watcher.second.sink.event(text);
        return true;
    });
}

std::vector<std::int64_t> LiveSession::sharedClasses() const
{
    std::lock_guard lock(mMutex);
    return {mSharedClasses.begin(), mSharedClasses.end()};
}

void LiveSession::record(const FrameSamples& samples)
{
    if (mRecording.full) return;
    LiveRecording& r = mRecording;
    const double t = samples.time.back();
    // A second frame of one step (a finished run, a live.step) replaces the first.
    const bool again = !r.samples.time.empty() && r.samples.time.back() == t;
    if (!again && r.samples.time.size() >= mConfig.maxRecordedSamples) {
        r.full = true;
        sendState(std::string("record_limit"),
                  "the recording holds at most " + std::to_string(mConfig.maxRecordedSamples) +
                      " samples (" + mConfig.recordLimit + "): later samples are not recorded; the session goes on");
        return;
    }
    if (!again) r.samples.time.push_back(t);
    for (std::size_t i = 0; i < r.samples.columns.size(); ++i) {
        auto& data = r.samples.columns[i].data;
        if (again) data.back() = samples.columns[i].back();
        else data.push_back(samples.columns[i].back());
    }
}

LiveRecording LiveSession::recording() const
{
    std::lock_guard lock(mMutex);
    LiveRecording copy = mRecording;
    copy.steps = mSimulation.takenSteps();
    return copy;
}

void LiveSession::unwatch(std::uint64_t watchId)
{
    std::lock_guard lock(mMutex);
    mWatchers.erase(watchId);
}

LiveSession::Reply LiveSession::state() const
{
    std::lock_guard lock(mMutex);
    if (mStopped) return liveRefusal("not_found", "the live session has ended");
    return stateReply();
}

void LiveSession::touch()
{
    std::lock_guard lock(mMutex);
    mLastTouch = mConfig.clock();
}

} // namespace tlmhub::server
