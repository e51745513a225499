#pragma once
// One WebSocket connection. Incoming text messages go to the handler one at a time; outgoing
// messages wait in a bounded queue. When a slow client lets the queue fill up, the oldest
// droppable message (a stream frame) is thrown away and counted, so a slow reader never
// holds up a simulation or other clients, and replies are never lost.
#include "server/http/Listener.h"
#include "server/http/OutgoingQueue.h"

#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include <atomic>

namespace tlmhub::server {

class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
public:
    WebSocketSession(boost::asio::ip::tcp::socket&& socket, TransportLimits limits);
    ~WebSocketSession();

    std::shared_ptr<WebSocketSender> sender();
    void start(Request upgradeRequest, std::shared_ptr<WebSocketHandler> handler);
    void refuse(Response refusal);

    // Called on the strand through the sender.
    void enqueue(std::string text, bool droppable);
    std::uint64_t droppedCount() const { return mDropped.load(); }   // any thread

private:
    void read();
    void writeNext();
    void closed();

    boost::beast::websocket::stream<boost::beast::tcp_stream> mWs;
    boost::beast::flat_buffer mBuffer;
    TransportLimits mLimits;
    std::shared_ptr<WebSocketHandler> mHandler;
    OutgoingQueue mQueue;
    bool mWriting = false;
    bool mOpen = false;
    std::atomic<std::uint64_t> mDropped{0};
};

} // namespace tlmhub::server
