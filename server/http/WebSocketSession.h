#pragma once
// One WebSocket connection. Incoming text messages go to the handler one at a time; outgoing
// messages wait in a queue bounded in count and bytes (OutgoingQueue): a slow reader gets
// merged stream frames (or event.resync past the byte limit), and one that lets replies pile
// up past the byte limit is disconnected and its buffers freed, so it never holds up a
// simulation, other clients or the server's memory. Once the connection ends (either side, or a failed write) the handler
// is told once and never called again.
#include "server/http/Listener.h"
#include "server/http/OutgoingQueue.h"

#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>


namespace tlmhub::server {

class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
public:
    WebSocketSession(boost::asio::ip::tcp::socket&& socket, TransportLimits limits);
    ~WebSocketSession();

    std::shared_ptr<WebSocketSender> sender();
    void start(Request upgradeRequest, std::shared_ptr<WebSocketHandler> handler);
    void refuse(Response refusal);

    // Called on the strand through the sender.
    void enqueue(std::string text);
    void enqueueReplaceable(std::string key, std::string text);
    void enqueueFrame(std::unique_ptr<MergeableFrame> frame);
    void closeWithReason(const std::string& reason);

private:
    void read();
    void writeNext();
    // Tells the handler (once) and frees the queue; the socket stays for a close handshake.
    void detach();
    // The connection is over: detach and close the socket, cancelling what is pending.
    void closed();
    void sendClose();   // the close handshake, with mCloseReason
    void afterEnqueue();
    void freeQueue();
    void trackQueuedBytes();

    boost::beast::websocket::stream<boost::beast::tcp_stream> mWs;
    boost::beast::flat_buffer mBuffer;
    TransportLimits mLimits;
    std::shared_ptr<WebSocketHandler> mHandler;
    OutgoingQueue mQueue;
    OutgoingMessage mWritten;   // the message being written, out of the queue
    std::string mCloseReason;
    std::size_t mCountedBytes = 0;   // this queue's share of TransportStats' gauge
    bool mWriting = false;
    bool mOpen = false;
    bool mClosing = false;
    bool mCounted = false;
};

} // namespace tlmhub::server
