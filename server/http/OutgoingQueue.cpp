#include "server/http/OutgoingQueue.h"

#include <algorithm>

namespace tlmhub::server {

bool OutgoingQueue::push(std::string text, bool droppable, bool frontInFlight)
{
    if (mItems.size() >= mLimit) {
        const auto first = mItems.begin() + (frontInFlight && !mItems.empty() ? 1 : 0);
        const auto oldest = std::find_if(first, mItems.end(), [](const Item& i) { return i.droppable; });
        if (oldest != mItems.end()) {
            mItems.erase(oldest);
            ++mDropped;
        } else if (droppable) {
            ++mDropped;   // only replies waiting: the new frame goes instead
            return false;
        }
    }
    mItems.push_back({std::move(text), droppable});
    return true;
}

} // namespace tlmhub::server
