#include "server/app/HandlerPools.h"

#include <boost/asio/post.hpp>

namespace tlmhub::server {

HandlerPools::HandlerPools(unsigned requestThreads, unsigned hashingThreads, std::size_t hashingQueueLimit,
                           unsigned largeReplyThreads)
    : mRequests(requestThreads), mHashing(hashingThreads), mLargeReplies(largeReplyThreads),
      mHashingQueueLimit(hashingQueueLimit)
{
}

HandlerPools::~HandlerPools()
{
    stop();
}

void HandlerPools::runRequest(std::function<void()> task)
{
    boost::asio::post(mRequests, std::move(task));
}

bool HandlerPools::runHashing(std::function<void()> task)
{
    if (mHashingPending.fetch_add(1) >= mHashingQueueLimit) {
        mHashingPending.fetch_sub(1);
        return false;
    }
    boost::asio::post(mHashing, [this, task = std::move(task)] {
        mHashingPending.fetch_sub(1);
        task();
    });
    return true;
}

bool HandlerPools::runLargeReply(std::int64_t userId, std::function<void(PerUserSlots::Slot)> task)
{
    PerUserSlots::Slot slot = mLargeReplySlots.tryTake(userId);
    if (!slot) return false;
    boost::asio::post(mLargeReplies, [task = std::move(task), slot = std::move(slot)]() mutable { task(std::move(slot)); });
    return true;
}

std::string HandlerPools::largeRepliesBusyMessage() const
{
    return "at most " + std::to_string(mLargeReplySlots.perUser()) +
           " large replies (a model, results, an FMU) are built at once per user; try again when one has come";
}

void HandlerPools::stop()
{
    mRequests.stop();
    mHashing.stop();
    mLargeReplies.stop();
    mRequests.join();
    mHashing.join();
    mLargeReplies.join();
}

} // namespace tlmhub::server
