#pragma once
// The boundary between the transport (sockets, HTTP parsing, WebSocket framing) and the
// application (routes, users, jobs). The transport knows nothing of tlmhub's API.
#include "server/http/HttpTypes.h"
#include "server/http/MergeableFrame.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace tlmhub::server {

class ConnectionOutbox;

// Sending side of one WebSocket connection; safe to call from any thread.
class WebSocketSender {
public:
    virtual ~WebSocketSender() = default;
    // Queues a reply or event; these are never dropped.
    virtual void send(std::string text) = 0;
    // Queues an event that states a level: it replaces the one with the same `key` (not
    // empty; the application's choice) that is still waiting to be sent (OutgoingQueue).
    virtual void sendReplaceable(std::string key, std::string text) = 0;
    // Queues a stream frame, which a slow connection merges with the next frames of its
    // stream, or gives up for the frame's notice past its byte limit (OutgoingQueue).
    virtual void sendFrame(std::unique_ptr<MergeableFrame> frame) = 0;
    // As sendFrame and send, handed to the I/O threads through `outbox` together with other
    // connections' messages of the same burst (live sessions' frames and states). A sender
    // without I/O threads of its own sends at once.
    virtual void sendFrameVia(ConnectionOutbox&, std::unique_ptr<MergeableFrame> frame) { sendFrame(std::move(frame)); }
    virtual void sendVia(ConnectionOutbox&, std::string text) { send(std::move(text)); }
    // Ends the connection with a close frame giving `reason`; nothing queued is sent after.
    virtual void close(std::string reason) = 0;
    // Runs `task` on the connection's strand (where its handler runs), unless the connection
    // has ended by then.
    virtual void runOnConnection(std::function<void()> task) = 0;
};

// Receiving side: one per connection, called on the connection's strand (one at a time).
class WebSocketHandler {
public:
    virtual ~WebSocketHandler() = default;
    virtual void onMessage(const std::string& text) = 0;
    virtual void onClose() = 0;
};

class HttpApplication {
public:
    using Reply = std::function<void(Response)>;
    virtual ~HttpApplication() = default;
    // Answers a request by calling `reply` once, at once or later on any thread; `in` stays
    // valid until then. An I/O thread calls this: what takes long must go elsewhere.
    virtual void handle(const Incoming& in, Reply reply) = 0;
    // A WebSocket upgrade request: a handler to accept it, or null with `refusal` filled.
    virtual std::shared_ptr<WebSocketHandler> acceptWebSocket(
        const Incoming& in, std::shared_ptr<WebSocketSender> sender, Response& refusal) = 0;
};

} // namespace tlmhub::server
