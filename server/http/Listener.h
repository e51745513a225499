#pragma once
// Accepts TCP connections and starts an HttpSession for each, on its own strand.
#include "server/http/HttpApplication.h"

#include <boost/asio/ip/tcp.hpp>

#include <memory>

namespace tlmhub::server {

struct TransportLimits {
    std::size_t maxBodyBytes = 8u << 20;
    std::size_t wsQueueLimit = 256;           // messages; past it a stream's frames merge
    std::size_t wsQueueBytes = 16u << 20;     // bytes; past it frames resync, then the socket closes
};

class Listener : public std::enable_shared_from_this<Listener> {
public:
    Listener(boost::asio::io_context& ioc, boost::asio::ip::tcp::endpoint endpoint,
             HttpApplication& app, TransportLimits limits);
    void run();
    void stop();
    boost::asio::ip::tcp::endpoint localEndpoint() const { return mAcceptor.local_endpoint(); }

private:
    void accept();

    boost::asio::io_context& mIoc;
    boost::asio::ip::tcp::acceptor mAcceptor;
    HttpApplication& mApp;
    TransportLimits mLimits;
};

} // namespace tlmhub::server
