#pragma once
// One HTTP connection: reads requests (bodies limited in size), answers them through the
// application, keeps the connection alive, and hands WebSocket upgrades over.
#include "server/http/Listener.h"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <optional>

namespace tlmhub::server {

class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
    HttpSession(boost::asio::ip::tcp::socket&& socket, HttpApplication& app, TransportLimits limits);
    void run();

private:
    void read();
    void onRead(boost::beast::error_code ec);
    // `headOnly`: the answer to a HEAD request (headers of the GET response, no body).
    void write(Response response, bool headOnly = false);
    void close();

    boost::beast::tcp_stream mStream;
    boost::beast::flat_buffer mBuffer;
    std::optional<http::request_parser<http::string_body>> mParser;
    HttpApplication& mApp;
    TransportLimits mLimits;
    std::string mClientAddress;
};

// An error response with the protocol's body {"error":{"code","message"}}.
Response errorResponse(http::status status, const std::string& code, const std::string& message,
                       unsigned version = 11, bool keepAlive = false);

} // namespace tlmhub::server
