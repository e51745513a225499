#include "server/auth/LiveSessions.h"

#include <utility>
#include <vector>

namespace tlmhub::server {

LiveSessions::LiveSessions(TokenCheck stillValid, std::chrono::milliseconds period)
    : mStillValid(std::move(stillValid)), mPeriod(period), mThread([this] { loop(); }) {}

LiveSessions::~LiveSessions()
{
    {
        std::lock_guard lock(mMutex);
        mStopping = true;
    }
    mWake.notify_all();
    mThread.join();
}

std::uint64_t LiveSessions::add(const std::string& token, std::int64_t userId,
                                std::shared_ptr<WebSocketSender> sender)
{
    std::lock_guard lock(mMutex);
    const std::uint64_t id = mNextId++;
    mEntries.emplace(id, Entry{token, userId, sender});
    return id;
}

void LiveSessions::remove(std::uint64_t id)
{
    std::lock_guard lock(mMutex);
    mEntries.erase(id);
}

int LiveSessions::sweep()
{
    std::vector<std::pair<std::uint64_t, Entry>> entries;
    {
        std::lock_guard lock(mMutex);
        entries.assign(mEntries.begin(), mEntries.end());
    }
    // Validation reads the database: outside our lock, so add/remove never wait on it.
    int closed = 0;
    for (const auto& [id, entry] : entries) {
        if (mStillValid(entry.token)) continue;
        if (auto sender = entry.sender.lock()) sender->close("login ended: log in again");
        remove(id);
        ++closed;
    }
    return closed;
}

int LiveSessions::closeAllOf(std::int64_t userId, const std::string& reason)
{
    std::vector<std::shared_ptr<WebSocketSender>> senders;
    {
        std::lock_guard lock(mMutex);
        for (auto it = mEntries.begin(); it != mEntries.end();) {
            if (it->second.userId != userId) {
                ++it;
                continue;
            }
            if (auto sender = it->second.sender.lock()) senders.push_back(std::move(sender));
            it = mEntries.erase(it);
        }
    }
    for (auto& sender : senders) sender->close(reason);
    return static_cast<int>(senders.size());
}

void LiveSessions::loop()
{
    std::unique_lock lock(mMutex);
    while (!mStopping) {
        mWake.wait_for(lock, mPeriod, [this] { return mStopping; });
        if (mStopping) break;
        lock.unlock();
        sweep();
        lock.lock();
    }
}

} // namespace tlmhub::server
