#include "server/http/WebSocketSession.h"

#include <boost/asio/post.hpp>

namespace tlmhub::server {

namespace beast = boost::beast;
namespace net = boost::asio;
namespace websocket = beast::websocket;

namespace {

// Posts each message onto the session's strand; outlives the session harmlessly.
class SessionSender : public WebSocketSender {
public:
    explicit SessionSender(std::weak_ptr<WebSocketSession> session, net::any_io_executor executor)
        : mSession(std::move(session)), mExecutor(std::move(executor)) {}

    void send(std::string text, bool droppable) override
    {
        net::post(mExecutor, [weak = mSession, text = std::move(text), droppable]() mutable {
            if (auto session = weak.lock()) session->enqueue(std::move(text), droppable);
        });
    }
    std::uint64_t droppedCount() const override
    {
        auto session = mSession.lock();
        return session ? session->droppedCount() : 0;
    }

private:
    std::weak_ptr<WebSocketSession> mSession;
    net::any_io_executor mExecutor;
};

} // namespace

WebSocketSession::WebSocketSession(net::ip::tcp::socket&& socket, TransportLimits limits)
    : mWs(std::move(socket)), mLimits(limits), mQueue(limits.wsQueueLimit) {}

WebSocketSession::~WebSocketSession() = default;

std::shared_ptr<WebSocketSender> WebSocketSession::sender()
{
    return std::make_shared<SessionSender>(weak_from_this(), mWs.get_executor());
}

void WebSocketSession::refuse(Response refusal)
{
    auto shared = std::make_shared<Response>(std::move(refusal));
    shared->keep_alive(false);
    shared->prepare_payload();
    http::async_write(mWs.next_layer(), *shared,
                      [self = shared_from_this(), shared](beast::error_code, std::size_t) {
                          beast::error_code ignored;
                          self->mWs.next_layer().socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
                      });
}

void WebSocketSession::start(Request upgradeRequest, std::shared_ptr<WebSocketHandler> handler)
{
    mHandler = std::move(handler);
    mWs.next_layer().expires_never();
    mWs.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    mWs.read_message_max(mLimits.maxBodyBytes);
    auto request = std::make_shared<Request>(std::move(upgradeRequest));
    mWs.async_accept(*request, [self = shared_from_this(), request](beast::error_code ec) {
        if (ec) return self->closed();
        self->mOpen = true;
        self->writeNext();   // messages queued by the handler before the handshake finished
        self->read();
    });
}

void WebSocketSession::read()
{
    mWs.async_read(mBuffer, [self = shared_from_this()](beast::error_code ec, std::size_t) {
        if (ec) return self->closed();
        std::string text = beast::buffers_to_string(self->mBuffer.data());
        self->mBuffer.consume(self->mBuffer.size());
        self->mHandler->onMessage(text);
        self->read();
    });
}

void WebSocketSession::enqueue(std::string text, bool droppable)
{
    mQueue.push(std::move(text), droppable, mWriting);
    mDropped.store(mQueue.dropped());
    writeNext();
}

void WebSocketSession::writeNext()
{
    if (mWriting || !mOpen || mQueue.empty()) return;
    mWriting = true;
    mWs.text(true);
    mWs.async_write(net::buffer(mQueue.front()),
                    [self = shared_from_this()](beast::error_code ec, std::size_t) {
                        self->mWriting = false;
                        if (ec) return self->closed();
                        self->mQueue.pop();
                        self->writeNext();
                    });
}

void WebSocketSession::closed()
{
    mOpen = false;
    mQueue.clear();
    if (mHandler) {
        mHandler->onClose();
        mHandler.reset();   // breaks the handler -> sender -> session cycle
    }
}

} // namespace tlmhub::server
