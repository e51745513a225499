#include "server/app/PerUserSlots.h"

namespace tlmhub::server {

PerUserSlots::Slot PerUserSlots::tryTake(std::int64_t userId)
{
    {
        std::lock_guard lock(mMutex);
        std::size_t& taken = mTaken[userId];
        if (taken >= mPerUser) return nullptr;
        ++taken;
    }
    // An empty allocation whose deleter gives the slot back.
    return Slot(static_cast<void*>(this), [this, userId](void*) { give(userId); });
}

void PerUserSlots::give(std::int64_t userId)
{
    std::lock_guard lock(mMutex);
    const auto it = mTaken.find(userId);
    if (it != mTaken.end() && --it->second == 0) mTaken.erase(it);
}

} // namespace tlmhub::server
