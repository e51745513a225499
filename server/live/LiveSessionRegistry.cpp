#include "server/live/LiveSessionRegistry.h"

#include <algorithm>
#include <vector>

namespace tlmhub::server {

LiveSessionRegistry::LiveSessionRegistry(Limits limits, unsigned threads,
                                         std::function<LivePacer::Clock::time_point()> clock)
    : mLimits(limits), mClock(std::move(clock)), mPool(std::max(1u, threads))
{
}

LiveSessionRegistry::~LiveSessionRegistry()
{
    stopAll();
    mPool.join();
}

std::optional<LiveSessionRegistry::Refusal> LiveSessionRegistry::reserve(std::int64_t userId)
{
    std::lock_guard lock(mMutex);
    std::size_t& mine = mPerUser[userId];
    if (mine >= mLimits.perUser)
        return Refusal{"rate_limited", "you already run " + std::to_string(mine) + " live sessions, the most a user may (" +
                                           std::to_string(mLimits.perUser) +
                                           ", --max-live-sessions-per-user): stop one first (live.stop)"};
    if (mTotal >= mLimits.perNode)
        return Refusal{"busy", "this server runs " + std::to_string(mTotal) + " live sessions, its limit (" +
                                   std::to_string(mLimits.perNode) + ", --max-live-sessions): try again later"};
    ++mine;
    ++mTotal;
    return std::nullopt;
}

void LiveSessionRegistry::release(std::int64_t userId)
{
    std::lock_guard lock(mMutex);
    if (auto it = mPerUser.find(userId); it != mPerUser.end() && it->second > 0 && --it->second == 0) mPerUser.erase(it);
    --mTotal;
}

std::shared_ptr<LiveSession> LiveSessionRegistry::create(LiveSessionConfig config, Simulation simulation,
                                                         std::vector<LiveVariable> variables, LiveSessionSink sink)
{
    std::unique_lock lock(mMutex);
    config.id = mNextId++;
    config.idleTimeout = mLimits.idleTimeout;
    config.clock = mClock;
    auto session = std::make_shared<LiveSession>(mPool.get_executor(), std::move(config), std::move(simulation),
                                                 std::move(variables), std::move(sink),
                                                 [this](std::uint64_t id) { ended(id); });
    mSessions.emplace(session->id(), session);
    lock.unlock();
    session->arm();
    return session;
}

std::shared_ptr<LiveSession> LiveSessionRegistry::find(std::uint64_t id) const
{
    std::lock_guard lock(mMutex);
    const auto it = mSessions.find(id);
    return it == mSessions.end() ? nullptr : it->second;
}

std::vector<std::shared_ptr<LiveSession>> LiveSessionRegistry::sharedWith(std::int64_t classId) const
{
    std::vector<std::shared_ptr<LiveSession>> sessions;
    {
        std::lock_guard lock(mMutex);
        for (const auto& [id, session] : mSessions) sessions.push_back(session);
    }
    // Asked outside the lock: a session ending holds its own lock and then takes this one.
    std::erase_if(sessions, [classId](const std::shared_ptr<LiveSession>& session) {
        const std::vector<std::int64_t> classes = session->sharedClasses();
        return std::find(classes.begin(), classes.end(), classId) == classes.end();
    });
    return sessions;
}

void LiveSessionRegistry::ended(std::uint64_t id)
{
    std::lock_guard lock(mMutex);
    const auto it = mSessions.find(id);
    if (it == mSessions.end()) return;
    const std::int64_t owner = it->second->ownerId();
    mSessions.erase(it);
    if (auto mine = mPerUser.find(owner); mine != mPerUser.end() && mine->second > 0 && --mine->second == 0)
        mPerUser.erase(mine);
    --mTotal;
}

void LiveSessionRegistry::stopAll()
{
    std::vector<std::shared_ptr<LiveSession>> sessions;
    {
        std::lock_guard lock(mMutex);
        for (const auto& [id, session] : mSessions) sessions.push_back(session);
    }
    // Outside the lock: a session's end comes back to ended().
    for (const auto& session : sessions) session->stop("shutdown");
}

} // namespace tlmhub::server
