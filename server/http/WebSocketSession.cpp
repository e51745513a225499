#include "server/http/WebSocketSession.h"

#include "server/http/ConnectionOutbox.h"
#include "server/http/TransportStats.h"

#include <boost/asio/post.hpp>

namespace tlmhub::server {

namespace beast = boost::beast;
namespace net = boost::asio;
namespace websocket = beast::websocket;

namespace {

// Posts each call onto the session's strand; outlives the session harmlessly.
class SessionSender : public WebSocketSender {
public:
    explicit SessionSender(std::weak_ptr<WebSocketSession> session, net::any_io_executor executor)
        : mSession(std::move(session)), mExecutor(std::move(executor)) {}

    void send(std::string text) override
    {
        net::post(mExecutor, [weak = mSession, text = std::move(text)]() mutable {
            if (auto session = weak.lock()) session->enqueue(std::move(text));
        });
    }
    void sendReplaceable(std::string key, std::string text) override
    {
        net::post(mExecutor, [weak = mSession, key = std::move(key), text = std::move(text)]() mutable {
            if (auto session = weak.lock()) session->enqueueReplaceable(std::move(key), std::move(text));
        });
    }
    void sendFrame(std::unique_ptr<MergeableFrame> frame) override
    {
        net::post(mExecutor, [weak = mSession, frame = std::move(frame)]() mutable {
            if (auto session = weak.lock()) session->enqueueFrame(std::move(frame));
        });
    }
    void sendFrameVia(ConnectionOutbox& outbox, std::unique_ptr<MergeableFrame> frame) override
    {
        // std::function is copyable: the frame travels in a shared pointer.
        auto shared = std::make_shared<std::unique_ptr<MergeableFrame>>(std::move(frame));
        outbox.add({mExecutor, [weak = mSession, shared] {
                        if (auto session = weak.lock()) session->enqueueFrame(std::move(*shared));
                    }});
    }
    void sendVia(ConnectionOutbox& outbox, std::string text) override
    {
        outbox.add({mExecutor, [weak = mSession, text = std::move(text)]() mutable {
                        if (auto session = weak.lock()) session->enqueue(std::move(text));
                    }});
    }
    void close(std::string reason) override
    {
        net::post(mExecutor, [weak = mSession, reason = std::move(reason)] {
            if (auto session = weak.lock()) session->closeWithReason(reason);
        });
    }
    void runOnConnection(std::function<void()> task) override
    {
        net::post(mExecutor, [weak = mSession, task = std::move(task)] {
            if (weak.lock()) task();
        });
    }

private:
    std::weak_ptr<WebSocketSession> mSession;
    net::any_io_executor mExecutor;
};

// A close handshake with a client that does not answer ends after this long.
constexpr auto kCloseTimeout = std::chrono::seconds(5);

} // namespace

WebSocketSession::WebSocketSession(net::ip::tcp::socket&& socket, TransportLimits limits)
    : mWs(std::move(socket)), mLimits(limits), mQueue(limits.wsQueueLimit, limits.wsQueueBytes) {}

WebSocketSession::~WebSocketSession()
{
    freeQueue();
    if (mCounted) --TransportStats::instance().webSockets;
}

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
    mCounted = true;
    ++TransportStats::instance().webSockets;
    mWs.next_layer().expires_never();
    auto timeouts = websocket::stream_base::timeout::suggested(beast::role_type::server);
    timeouts.handshake_timeout = kCloseTimeout;
    mWs.set_option(timeouts);
    mWs.read_message_max(mLimits.maxBodyBytes);
    auto request = std::make_shared<Request>(std::move(upgradeRequest));
    mWs.async_accept(*request, [self = shared_from_this(), request](beast::error_code ec) {
        if (ec) return self->closed();
        if (self->mClosing) return;
        self->mOpen = true;
        self->writeNext();   // messages queued by the handler before the handshake finished
        self->read();
    });
}

void WebSocketSession::read()
{
    mWs.async_read(mBuffer, [self = shared_from_this()](beast::error_code ec, std::size_t) {
        if (ec) return self->closed();
        if (!self->mHandler) return;   // ended while this message arrived
        std::string text = beast::buffers_to_string(self->mBuffer.data());
        self->mBuffer.consume(self->mBuffer.size());
        self->mHandler->onMessage(text);
        if (self->mHandler) self->read();
    });
}

void WebSocketSession::enqueue(std::string text)
{
    if (mClosing) return;
    mQueue.push(std::move(text));
    afterEnqueue();
}

void WebSocketSession::enqueueReplaceable(std::string key, std::string text)
{
    if (mClosing) return;
    mQueue.pushReplaceable(std::move(key), std::move(text));
    afterEnqueue();
}

void WebSocketSession::enqueueFrame(std::unique_ptr<MergeableFrame> frame)
{
    if (mClosing) return;
    mQueue.push(std::move(frame));
    afterEnqueue();
}

void WebSocketSession::afterEnqueue()
{
    trackQueuedBytes();
    if (mQueue.overflowing()) {
        // Replies alone fill the limit: the client is not reading. Free the memory now; a
        // close handshake could not get through a full socket anyway.
        ++TransportStats::instance().webSocketsClosedForBacklog;
        return closed();
    }
    writeNext();
}

void WebSocketSession::writeNext()
{
    if (mWriting || !mOpen || mClosing || mQueue.empty()) return;
    mWriting = true;
    mWritten = mQueue.takeNext();
    trackQueuedBytes();
    mWs.binary(mWritten.binary);
    mWs.async_write(net::buffer(mWritten.data),
                    [self = shared_from_this()](beast::error_code ec, std::size_t) {
                        self->mWriting = false;
                        self->mQueue.written();
                        std::string().swap(self->mWritten.data);   // a merged frame can be megabytes
                        if (ec) return self->closed();
                        if (self->mClosing) return self->sendClose();
                        self->trackQueuedBytes();
                        self->writeNext();
                    });
}

void WebSocketSession::closeWithReason(const std::string& reason)
{
    if (mClosing) return;
    mCloseReason = reason;
    detach();
    if (!mOpen) return closed();
    if (!mWriting) sendClose();   // else once the frame being written is out
}

void WebSocketSession::sendClose()
{
    freeQueue();
    mWs.async_close(websocket::close_reason(websocket::close_code::policy_error, mCloseReason),
                    [self = shared_from_this()](beast::error_code) { self->closed(); });
}

void WebSocketSession::detach()
{
    mClosing = true;
    if (!mWriting) freeQueue();
    if (mHandler) {
        std::shared_ptr<WebSocketHandler> handler = std::move(mHandler);   // no call after this
        handler->onClose();   // breaks the handler -> sender -> session cycle when it goes
    }
}

void WebSocketSession::closed()
{
    detach();
    mOpen = false;
    beast::get_lowest_layer(mWs).close();
    if (!mWriting) freeQueue();
}

// Also the message last written: it is only freed here (a write in flight reads it).
void WebSocketSession::freeQueue()
{
    mQueue.clear();
    std::string().swap(mWritten.data);
    trackQueuedBytes();
}

void WebSocketSession::trackQueuedBytes()
{
    const auto now = mQueue.bytes();
    TransportStats::instance().webSocketQueuedBytes += static_cast<std::int64_t>(now) -
                                                       static_cast<std::int64_t>(mCountedBytes);
    mCountedBytes = now;
}

} // namespace tlmhub::server
