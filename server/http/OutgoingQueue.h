#pragma once
// Messages waiting to be written to one WebSocket. Bounded: when full, the oldest droppable
// message (a stream frame) makes room and is counted; replies are never dropped. The message
// being written (the front, while a write is in flight) is never touched.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>

namespace tlmhub::server {

class OutgoingQueue {
public:
    explicit OutgoingQueue(std::size_t limit) : mLimit(limit) {}

    // Returns false if the message itself was dropped (full of replies, message droppable).
    bool push(std::string text, bool droppable, bool frontInFlight);
    bool empty() const { return mItems.empty(); }
    std::size_t size() const { return mItems.size(); }
    const std::string& front() const { return mItems.front().text; }
    void pop() { mItems.pop_front(); }
    void clear() { mItems.clear(); }
    std::uint64_t dropped() const { return mDropped; }

private:
    struct Item {
        std::string text;
        bool droppable;
    };
    std::size_t mLimit;
    std::deque<Item> mItems;
    std::uint64_t mDropped = 0;
};

} // namespace tlmhub::server
