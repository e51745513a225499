#include "server/http/ConnectionOutbox.h"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

namespace tlmhub::server {

ConnectionOutbox::ConnectionOutbox(boost::asio::any_io_executor collectOn) : mCollectOn(std::move(collectOn)) {}

void ConnectionOutbox::add(Delivery delivery)
{
    std::lock_guard lock(mShared->mutex);
    mShared->pending.push_back(std::move(delivery));
    if (mShared->flushPosted) return;
    mShared->flushPosted = true;
    boost::asio::post(mCollectOn, [shared = mShared] { flush(shared); });
}

void ConnectionOutbox::flush(const std::shared_ptr<Shared>& shared)
{
    std::vector<Delivery> batch;
    {
        std::lock_guard lock(shared->mutex);
        batch.swap(shared->pending);
        shared->flushPosted = false;
    }
    if (batch.empty()) return;
    // One post wakes one I/O thread; there each delivery dispatches onto its connection's
    // strand, which runs it in place when the strand is free.
    auto first = batch.front().connection;
    boost::asio::post(first, [batch = std::move(batch)]() mutable {
        for (Delivery& d : batch) boost::asio::dispatch(d.connection, std::move(d.deliver));
    });
}

} // namespace tlmhub::server
