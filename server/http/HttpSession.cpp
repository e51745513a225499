#include "server/http/HttpSession.h"

#include "server/http/HeaderValues.h"
#include "server/http/JsonText.h"
#include "server/http/SecurityHeaders.h"
#include "server/http/WebSocketSession.h"

#include <boost/asio/dispatch.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include <chrono>

namespace tlmhub::server {

namespace beast = boost::beast;
namespace net = boost::asio;

namespace {
constexpr auto kIdleTimeout = std::chrono::seconds(60);
}

Response errorResponse(http::status status, const std::string& code, const std::string& message,
                       unsigned version, bool keepAlive)
{
    Response res{status, version};
    res.set(http::field::content_type, "application/json");
    res.keep_alive(keepAlive);
    res.body() = toJsonText({{"error", {{"code", code}, {"message", message}}}});
    res.prepare_payload();
    return res;
}

HttpSession::HttpSession(net::ip::tcp::socket&& socket, HttpApplication& app, TransportLimits limits)
    : mStream(std::move(socket)), mApp(app), mLimits(limits)
{
    beast::error_code ec;
    const auto remote = mStream.socket().remote_endpoint(ec);
    if (!ec) mClientAddress = remote.address().to_string();
}

void HttpSession::run()
{
    net::dispatch(mStream.get_executor(), [self = shared_from_this()] { self->read(); });
}

void HttpSession::read()
{
    mParser.emplace();
    mParser->body_limit(mLimits.maxBodyBytes);
    mStream.expires_after(kIdleTimeout);
    http::async_read(mStream, mBuffer, *mParser,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->onRead(ec); });
}

void HttpSession::onRead(beast::error_code ec)
{
    if (ec == http::error::end_of_stream || ec == beast::error::timeout ||
        ec == net::error::connection_reset || ec == net::error::operation_aborted)
        return close();
    if (ec == http::error::body_limit) {
        return write(errorResponse(http::status::payload_too_large, "payload_too_large",
                                   "request body exceeds the limit of " +
                                       std::to_string(mLimits.maxBodyBytes) + " bytes"));
    }
    if (ec) {
        return write(errorResponse(http::status::bad_request, "bad_request",
                                   "malformed HTTP request: " + ec.message()));
    }
    auto request = std::make_shared<Request>(mParser->release());
    if (beast::websocket::is_upgrade(*request)) {
        const Incoming in{*request, mClientAddress};
        auto wsSession = std::make_shared<WebSocketSession>(mStream.release_socket(), mLimits);
        Response refusal;
        auto handler = mApp.acceptWebSocket(in, wsSession->sender(), refusal);
        if (!handler) {
            // Answer the refused upgrade as plain HTTP on the socket the session now owns.
            wsSession->refuse(std::move(refusal));
            return;
        }
        wsSession->start(std::move(*request), std::move(handler));
        return;
    }
    // The reply may come from another thread: it is written on this session's strand. The
    // next request is read only after it, so a request is handled one at a time per session.
    auto reply = [self = shared_from_this(), request](Response response) {
        net::dispatch(self->mStream.get_executor(), [self, request, response = std::move(response)]() mutable {
            response.version(request->version());
            response.keep_alive(request->keep_alive());
            self->write(std::move(response), request->method() == http::verb::head);
        });
    };
    try {
        mApp.handle(Incoming{*request, mClientAddress}, reply);
    } catch (const std::exception& e) {
        reply(errorResponse(http::status::internal_server_error, "internal", e.what()));
    }
}

void HttpSession::write(Response response, bool headOnly)
{
    // A header value with a line break would let its author add headers or a whole response.
    if (!hasSafeHeaders(response))
        response = errorResponse(http::status::internal_server_error, "internal",
                                 "refused to send a response header with a control character",
                                 response.version(), response.keep_alive());
    addSecurityHeaders(response);
    auto shared = std::make_shared<Response>(std::move(response));
    shared->prepare_payload();
    if (headOnly) {
        // The length of the body a GET would get, but no body: the next response on a
        // kept-alive connection must start right after the header.
        const auto length = shared->body().size();
        shared->body().clear();
        shared->content_length(length);
    }
    http::async_write(mStream, *shared, [self = shared_from_this(), shared](beast::error_code ec, std::size_t) {
        if (ec || !shared->keep_alive()) return self->close();
        self->read();
    });
}

void HttpSession::close()
{
    beast::error_code ignored;
    mStream.socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
}

} // namespace tlmhub::server
