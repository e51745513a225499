#pragma once
// The live sessions running on this node, their limits (per user and per node), and the
// threads their ticks run on. A session belongs to the connection that started it; the
// registry finds it by id for its owner's controls.
#include "server/http/ConnectionOutbox.h"
#include "server/live/LiveSession.h"

#include <boost/asio/thread_pool.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

class LiveSessionRegistry {
public:
    struct Limits {
        std::size_t perUser = 2;
        std::size_t perNode = 64;
        std::chrono::milliseconds idleTimeout{600'000};
    };
    struct Refusal {
        std::string code, message;
    };

    // `threads` run every session's ticks; `clock` paces them (tests inject one).
    LiveSessionRegistry(Limits limits, unsigned threads,
                        std::function<LivePacer::Clock::time_point()> clock = [] { return LivePacer::Clock::now(); });
    // Stops every session (reason shutdown) and waits for their ticks.
    ~LiveSessionRegistry();
    LiveSessionRegistry(const LiveSessionRegistry&) = delete;
    LiveSessionRegistry& operator=(const LiveSessionRegistry&) = delete;

    // Holds a place for one more session of `userId` while its model compiles; a refusal
    // names the limit and its flag. Every reserve is followed by create or release.
    std::optional<Refusal> reserve(std::int64_t userId);
    void release(std::int64_t userId);
    // The session in the place reserve held (config's id, idle timeout and clock are set here).
    std::shared_ptr<LiveSession> create(LiveSessionConfig config, Simulation simulation,
                                        std::vector<LiveVariable> variables, LiveSessionSink sink);
    // A running session, or null.
    std::shared_ptr<LiveSession> find(std::uint64_t id) const;
    // The running sessions shared with class `classId` (LiveSession::share).
    std::vector<std::shared_ptr<LiveSession>> sharedWith(std::int64_t classId) const;
    // Stops every session, as at shutdown.
    void stopAll();
    // Where the sessions' frames and states leave for their connections: after each burst
    // of ticks, in one post to the I/O threads.
    ConnectionOutbox& outbox() { return mOutbox; }

private:
    void ended(std::uint64_t id);

    const Limits mLimits;
    const std::function<LivePacer::Clock::time_point()> mClock;
    mutable std::mutex mMutex;
    std::map<std::uint64_t, std::shared_ptr<LiveSession>> mSessions;
    std::map<std::int64_t, std::size_t> mPerUser;   // sessions and reserved places
    std::size_t mTotal = 0;
    std::uint64_t mNextId = 1;
    boost::asio::thread_pool mPool;
    ConnectionOutbox mOutbox{mPool.get_executor()};
};

} // namespace tlmhub::server
