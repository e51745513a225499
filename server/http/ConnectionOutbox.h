#pragma once
// Hands messages for many WebSocket connections to the I/O threads in one post. Live sessions
// tick together on a common grid, and their frames, posted to the connections one by one,
// woke an I/O thread for nearly every frame (perf on 40 sessions at 30 frames a second: a
// quarter of the server's CPU in the kernel's context switches). Messages gathered here run
// on one I/O thread, each on its connection's strand, in the order they were added.
#include <boost/asio/any_io_executor.hpp>

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace tlmhub::server {

class ConnectionOutbox {
public:
    // `deliver` runs on the connection's strand.
    struct Delivery {
        boost::asio::any_io_executor connection;
        std::function<void()> deliver;
    };

    // The gathered deliveries leave in a handler posted to `collectOn`: posted behind the
    // ticks already queued there, it runs when the burst they belong to has ended.
    explicit ConnectionOutbox(boost::asio::any_io_executor collectOn);

    // Any thread. Deliveries to one connection keep their order.
    void add(Delivery delivery);

private:
    struct Shared {
        std::mutex mutex;
        std::vector<Delivery> pending;
        bool flushPosted = false;
    };
    static void flush(const std::shared_ptr<Shared>& shared);

    boost::asio::any_io_executor mCollectOn;
    std::shared_ptr<Shared> mShared = std::make_shared<Shared>();
};

} // namespace tlmhub::server
