#include "server/app/FairTaskQueue.h"

#include <boost/asio/post.hpp>

#include <tuple>

namespace tlmhub::server {

FairTaskQueue::FairTaskQueue(unsigned threads, std::size_t maxRunningPerUser, std::size_t maxQueuedPerUser)
    : mThreads(threads), mMaxRunningPerUser(maxRunningPerUser), mMaxQueuedPerUser(maxQueuedPerUser), mPool(threads)
{
}

FairTaskQueue::~FairTaskQueue()
{
    stop();
}

bool FairTaskQueue::submit(std::int64_t userId, std::function<void()> task)
{
    std::lock_guard lock(mMutex);
    if (mStopped) return true;   // shutting down: it would never run, and no one waits for it
    User& user = mUsers[userId];
    if (user.waiting.size() >= mMaxQueuedPerUser) return false;
    user.waiting.emplace_back(++mArrivals, std::move(task));
    startWaiting();
    return true;
}

void FairTaskQueue::startWaiting()
{
    while (mRunningTotal < mThreads && !mStopped) {
        // The user served least recently, then the one waiting longest.
        auto next = mUsers.end();
        for (auto it = mUsers.begin(); it != mUsers.end(); ++it) {
            const User& u = it->second;
            if (u.waiting.empty() || u.running >= mMaxRunningPerUser) continue;
            if (next == mUsers.end() || std::tie(u.lastStart, u.waiting.front().first) <
                                            std::tie(next->second.lastStart, next->second.waiting.front().first))
                next = it;
        }
        if (next == mUsers.end()) return;
        const std::int64_t userId = next->first;
        User& user = next->second;
        std::function<void()> task = std::move(user.waiting.front().second);
        user.waiting.pop_front();
        ++user.running;
        user.lastStart = ++mStarts;
        ++mRunningTotal;
        boost::asio::post(mPool, [this, userId, task = std::move(task)] {
            task();
            finished(userId);
        });
    }
}

void FairTaskQueue::finished(std::int64_t userId)
{
    std::lock_guard lock(mMutex);
    User& user = mUsers[userId];
    --user.running;
    --mRunningTotal;
    // A user with nothing left is forgotten: served next time as one who never was. Their
    // last start only orders users who wait at the same time.
    if (user.running == 0 && user.waiting.empty()) mUsers.erase(userId);
    startWaiting();
}

void FairTaskQueue::stop()
{
    {
        std::lock_guard lock(mMutex);
        mStopped = true;
        for (auto& [id, user] : mUsers) user.waiting.clear();
    }
    mPool.join();
}

} // namespace tlmhub::server
