#pragma once
// Messages waiting to be written to one WebSocket, bounded twice:
// - by count: at the limit, a stream frame is merged into the last waiting frame of its
//   stream (its samples appended: a slow client gets fewer, larger frames, never fewer
//   samples). A frame whose stream has none waiting is queued anyway, so the count can pass
//   the limit by one frame per stream; the byte limit still holds.
// - by bytes: past the limit, the stream with the most bytes waiting gives way to its notice
//   (event.resync: the client reads the stored result instead), until the queue fits again.
//   If replies and notices alone pass the limit the queue reports itself overflowing (the
//   session then closes: a client that never reads must not hold the server's memory).
// A replaceable message states a level (only its latest value matters, like a job's
// progress): a newer one with the same key replaces the one still waiting, in its place, so
// a slow client gets one per key and a stream of later messages cannot keep pushing it back.
// Other replies and events are never dropped, merged or reordered. The message being written
// has left the queue (takeNext), so nothing here can touch it, but its bytes count until it is
// written.
#include "server/http/MergeableFrame.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <string>

namespace tlmhub::server {

class OutgoingQueue {
public:
    explicit OutgoingQueue(std::size_t limit, std::size_t byteLimit = std::numeric_limits<std::size_t>::max())
        : mLimit(limit), mByteLimit(byteLimit) {}

    void push(std::string text);   // a reply or event: always queued
    // Replaces the waiting message with this `key` (not empty), else queues like push(text).
    void pushReplaceable(std::string key, std::string text);
    // A frame of a stream that was given up is discarded: its client reads the stored result.
    void push(std::unique_ptr<MergeableFrame> frame);
    bool empty() const { return mItems.empty(); }
    std::size_t size() const { return mItems.size(); }
    std::size_t bytes() const { return mBytes; }
    bool overflowing() const { return mBytes > mByteLimit; }
    // Removes the first message and returns it (a waiting frame is encoded now); its bytes
    // count until written().
    OutgoingMessage takeNext();
    void written();
    void clear();

private:
    struct Item {
        std::string text;                        // a reply, event or notice; empty for a frame
        std::unique_ptr<MergeableFrame> frame;   // a frame, still data
        std::size_t bytes = 0;
        std::string key;                         // of a replaceable message, else empty
    };
    void add(Item item);
    // The stream's last waiting frame, or null.
    Item* lastFrameOf(std::uint64_t stream);
    void giveUpStreamsPastTheByteLimit();
    // The stream's first frame becomes its notice; its other frames go.
    void giveUp(std::uint64_t stream);

    std::size_t mLimit;
    std::size_t mByteLimit;
    std::deque<Item> mItems;
    std::size_t mBytes = 0;      // waiting and being written
    std::size_t mInFlight = 0;   // being written
};

} // namespace tlmhub::server
