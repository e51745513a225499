#pragma once
// Runs users' tasks on a pool of `threads`, users taking turns: of the users with a waiting
// task who may run one more (at most `maxRunningPerUser` each), the one served least recently
// goes first, so a user who has not run yet goes ahead of one whose tasks already run. At
// most `maxQueuedPerUser` of one user's tasks wait. Lab check runs go through it: four slow
// pretests of one student no longer hold another's.
#include <boost/asio/thread_pool.hpp>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>

namespace tlmhub::server {

class FairTaskQueue {
public:
    FairTaskQueue(unsigned threads, std::size_t maxRunningPerUser, std::size_t maxQueuedPerUser);
    ~FairTaskQueue();
    FairTaskQueue(const FairTaskQueue&) = delete;
    FairTaskQueue& operator=(const FairTaskQueue&) = delete;

    // False (and `task` not taken) when `userId` has maxQueuedPerUser tasks waiting already.
    bool submit(std::int64_t userId, std::function<void()> task);
    // Waits for the running tasks; waiting ones never run.
    void stop();

private:
    struct User {
        std::deque<std::pair<std::uint64_t, std::function<void()>>> waiting;   // (arrival, task)
        std::size_t running = 0;
        std::uint64_t lastStart = 0;   // 0: never served
    };
    // Under mMutex: starts waiting tasks while a thread is free and someone may run one more.
    void startWaiting();
    void finished(std::int64_t userId);

    const unsigned mThreads;
    const std::size_t mMaxRunningPerUser, mMaxQueuedPerUser;
    std::mutex mMutex;
    std::map<std::int64_t, User> mUsers;   // users with tasks waiting or running
    std::uint64_t mArrivals = 0, mStarts = 0;
    unsigned mRunningTotal = 0;
    bool mStopped = false;
    boost::asio::thread_pool mPool;
};

} // namespace tlmhub::server
