#include "server/http/Listener.h"

#include "server/http/HttpSession.h"

#include <boost/asio/strand.hpp>

#include <iostream>

namespace tlmhub::server {

namespace net = boost::asio;
using tcp = net::ip::tcp;

Listener::Listener(net::io_context& ioc, tcp::endpoint endpoint, HttpApplication& app,
                   TransportLimits limits)
    : mIoc(ioc), mAcceptor(net::make_strand(ioc)), mApp(app), mLimits(limits)
{
    mAcceptor.open(endpoint.protocol());
    mAcceptor.set_option(net::socket_base::reuse_address(true));
    mAcceptor.bind(endpoint);   // throws with the reason (address in use, ...)
    mAcceptor.listen(net::socket_base::max_listen_connections);
}

void Listener::run() { accept(); }

void Listener::stop()
{
    net::post(mAcceptor.get_executor(), [self = shared_from_this()] {
        boost::system::error_code ignored;
        self->mAcceptor.close(ignored);
    });
}

void Listener::accept()
{
    mAcceptor.async_accept(net::make_strand(mIoc), [self = shared_from_this()](
                                                       boost::system::error_code ec, tcp::socket socket) {
        if (ec == net::error::operation_aborted || !self->mAcceptor.is_open()) return;
        if (!ec) {
            // A frame or reply goes out when written: with Nagle's algorithm a small write waited
            // for the ACK of the one before, which the client delays by up to 40 ms (a live
            // session's live.set showed in a frame after 43 ms at the median instead of 17).
            boost::system::error_code ignored;
            socket.set_option(tcp::no_delay(true), ignored);
            std::make_shared<HttpSession>(std::move(socket), self->mApp, self->mLimits)->run();
        }
        self->accept();
    });
}

} // namespace tlmhub::server
