#pragma once
// Messages waiting to be written to one WebSocket. Bounded twice: by count, where the oldest
// droppable message (a stream frame) makes room and is counted, and by bytes, where frames go
// first and, if replies alone pass the byte limit, the queue reports itself overflowing (the
// session then closes: a client that never reads must not hold the server's memory). Replies
// are never dropped; the message being written (the front, while a write is in flight) is
// never touched.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <string>

namespace tlmhub::server {

class OutgoingQueue {
public:
    explicit OutgoingQueue(std::size_t limit, std::size_t byteLimit = std::numeric_limits<std::size_t>::max())
        : mLimit(limit), mByteLimit(byteLimit) {}

    // Returns false if the message itself was dropped (full of replies, message droppable).
    bool push(std::string text, bool droppable, bool frontInFlight);
    bool empty() const { return mItems.empty(); }
    std::size_t size() const { return mItems.size(); }
    std::size_t bytes() const { return mBytes; }
    bool overflowing() const { return mBytes > mByteLimit; }
    const std::string& front() const { return mItems.front().text; }
    void pop();
    void clear();
    std::uint64_t dropped() const { return mDropped; }

private:
    struct Item {
        std::string text;
        bool droppable;
    };
    // Drops the oldest droppable message that is not in flight; false if there is none.
    bool dropOldestFrame(bool frontInFlight);

    std::size_t mLimit;
    std::size_t mByteLimit;
    std::deque<Item> mItems;
    std::size_t mBytes = 0;
    std::uint64_t mDropped = 0;
};

} // namespace tlmhub::server
