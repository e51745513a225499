#pragma once
// The threads slow work runs on, so no I/O thread waits for storage, a password hash or a
// model's compile: a request pool for REST handlers that touch the database (and jobs
// submitted over WebSocket, compiled there), and a smaller pool for password hashing
// (argon2id at its interactive limits takes tens of milliseconds of CPU per call).
// The hashing pool is bounded: forty students logging in at once queue there, while other
// requests and health probes go on.
// A third pool builds large replies (a model's JSON over REST or WebSocket, a run's results, an
// FMU), so they hold up neither the request pool nor each other's users: at most two of one
// user's at a time. Lab check runs have a queue of their own where users take turns
// (FairTaskQueue).
#include "server/app/PerUserSlots.h"

#include <boost/asio/thread_pool.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace tlmhub::server {

class HandlerPools {
public:
    HandlerPools(unsigned requestThreads, unsigned hashingThreads, std::size_t hashingQueueLimit,
                 unsigned largeReplyThreads);
    ~HandlerPools();
    HandlerPools(const HandlerPools&) = delete;
    HandlerPools& operator=(const HandlerPools&) = delete;

    void runRequest(std::function<void()> task);
    // False (and `task` not run) when `hashingQueueLimit` hashing tasks are already waiting.
    bool runHashing(std::function<void()> task);
    // False (and `task` not run) when `userId` has as many large replies being built as
    // largeRepliesPerUser(). `task` gets the user's slot and drops it once the reply is built,
    // before handing it on: a client that sends its next request on the reply then finds
    // the slot free.
    bool runLargeReply(std::int64_t userId, std::function<void(PerUserSlots::Slot)> task);
    // What a refused large reply tells its user.
    std::string largeRepliesBusyMessage() const;
    // Waits for the tasks already started; later ones do not run.
    void stop();

private:
    boost::asio::thread_pool mRequests;
    boost::asio::thread_pool mHashing;
    boost::asio::thread_pool mLargeReplies;
    const std::size_t mHashingQueueLimit;
    std::atomic<std::size_t> mHashingPending{0};
    PerUserSlots mLargeReplySlots{2};
};

} // namespace tlmhub::server
