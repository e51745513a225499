#include "server/http/OutgoingQueue.h"

#include <algorithm>
#include <cassert>
#include <map>

namespace tlmhub::server {

void OutgoingQueue::push(std::string text)
{
    const std::size_t size = text.size();
    add({std::move(text), nullptr, size, {}});
}

void OutgoingQueue::pushReplaceable(std::string key, std::string text)
{
    assert(!key.empty());   // an empty key would match every plain reply
    const auto waiting = std::find_if(mItems.begin(), mItems.end(), [&key](const Item& item) { return item.key == key; });
    if (waiting == mItems.end()) {
        const std::size_t size = text.size();
        return add({std::move(text), nullptr, size, std::move(key)});
    }
    mBytes = mBytes - waiting->bytes + text.size();
    waiting->bytes = text.size();
    waiting->text = std::move(text);
    giveUpStreamsPastTheByteLimit();
}

void OutgoingQueue::push(std::unique_ptr<MergeableFrame> frame)
{
    if (frame->streamGivenUp()) return;
    if (mItems.size() >= mLimit) {
        if (Item* waiting = lastFrameOf(frame->stream())) {
            mBytes -= waiting->bytes;
            waiting->frame->merge(*frame);
            waiting->bytes = waiting->frame->bytes();
            mBytes += waiting->bytes;
            return giveUpStreamsPastTheByteLimit();
        }
    }
    const std::size_t size = frame->bytes();
    add({{}, std::move(frame), size, {}});
}

void OutgoingQueue::add(Item item)
{
    mBytes += item.bytes;
    mItems.push_back(std::move(item));
    giveUpStreamsPastTheByteLimit();
}

OutgoingQueue::Item* OutgoingQueue::lastFrameOf(std::uint64_t stream)
{
    for (auto it = mItems.rbegin(); it != mItems.rend(); ++it)
        if (it->frame && it->frame->stream() == stream) return &*it;
    return nullptr;
}

void OutgoingQueue::giveUpStreamsPastTheByteLimit()
{
    while (overflowing()) {
        // The stream holding the most is the one furthest behind; a connection has few streams.
        std::map<std::uint64_t, std::size_t> waiting;
        for (const Item& item : mItems)
            if (item.frame) waiting[item.frame->stream()] += item.bytes;
        if (waiting.empty()) return;   // replies alone: overflowing() stays true
        const auto most = std::max_element(waiting.begin(), waiting.end(),
                                           [](const auto& a, const auto& b) { return a.second < b.second; });
        giveUp(most->first);
    }
}

void OutgoingQueue::giveUp(std::uint64_t stream)
{
    auto isFrameOf = [stream](const Item& item) { return item.frame && item.frame->stream() == stream; };
    // The notice takes the place of the first frame, so it comes before event.done (queued
    // after every frame of its stream).
    const auto first = std::find_if(mItems.begin(), mItems.end(), isFrameOf);
    first->text = first->frame->giveUp();
    first->frame.reset();
    mBytes -= first->bytes;
    first->bytes = first->text.size();
    mBytes += first->bytes;
    for (auto it = std::next(first); it != mItems.end();) {
        if (isFrameOf(*it)) {
            mBytes -= it->bytes;
            it = mItems.erase(it);
        } else {
            ++it;
        }
    }
}

OutgoingMessage OutgoingQueue::takeNext()
{
    Item item = std::move(mItems.front());
    mItems.pop_front();
    OutgoingMessage message = item.frame ? item.frame->message() : OutgoingMessage{std::move(item.text)};
    mBytes = mBytes - item.bytes + message.data.size();
    mInFlight = message.data.size();
    return message;
}

void OutgoingQueue::written()
{
    mBytes -= mInFlight;
    mInFlight = 0;
}

void OutgoingQueue::clear()
{
    mItems.clear();
    mItems.shrink_to_fit();
    mBytes = 0;
    mInFlight = 0;
}

} // namespace tlmhub::server
