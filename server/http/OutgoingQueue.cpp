#include "server/http/OutgoingQueue.h"

#include <algorithm>

namespace tlmhub::server {

bool OutgoingQueue::dropOldestFrame(bool frontInFlight)
{
    const auto first = mItems.begin() + (frontInFlight && !mItems.empty() ? 1 : 0);
    const auto oldest = std::find_if(first, mItems.end(), [](const Item& i) { return i.droppable; });
    if (oldest == mItems.end()) return false;
    mBytes -= oldest->text.size();
    mItems.erase(oldest);
    ++mDropped;
    return true;
}

bool OutgoingQueue::push(std::string text, bool droppable, bool frontInFlight)
{
    if (mItems.size() >= mLimit && !dropOldestFrame(frontInFlight) && droppable) {
        ++mDropped;   // only replies waiting: the new frame goes instead
        return false;
    }
    const auto first = mItems.begin() + (frontInFlight && !mItems.empty() ? 1 : 0);
    const auto olderFrames = std::count_if(first, mItems.end(), [](const Item& i) { return i.droppable; });
    mBytes += text.size();
    mItems.push_back({std::move(text), droppable});
    std::ptrdiff_t drops = 0;
    while (overflowing() && dropOldestFrame(frontInFlight)) ++drops;
    return drops <= olderFrames;   // more drops than older frames: the new one went too
}

void OutgoingQueue::pop()
{
    mBytes -= mItems.front().text.size();
    mItems.pop_front();
}

void OutgoingQueue::clear()
{
    mItems.clear();
    mItems.shrink_to_fit();
    mBytes = 0;
}

} // namespace tlmhub::server
