#include "server/studies/StudyProgressHub.h"

#include <algorithm>

namespace tlmhub::server {

std::uint64_t StudyProgressHub::subscribe(std::int64_t studyId, Sink sink)
{
    std::lock_guard lock(mMutex);
    if (const auto finished = mFinished.find(studyId); finished != mFinished.end()) {
        sink(finished->second);
        return 0;
    }
    const std::uint64_t id = mNextId++;
    mSubscriptions.emplace(id, Subscription{studyId, std::move(sink)});
    return id;
}

void StudyProgressHub::unsubscribe(std::uint64_t subscription)
{
    std::lock_guard lock(mMutex);
    mSubscriptions.erase(subscription);
}

std::uint64_t StudyProgressHub::current(std::int64_t studyId) const
{
    const auto found = mGenerations.find(studyId);
    return found == mGenerations.end() ? 0 : found->second;
}

std::uint64_t StudyProgressHub::generation(std::int64_t studyId) const
{
    std::lock_guard lock(mMutex);
    return current(studyId);
}

void StudyProgressHub::publish(std::int64_t studyId, std::uint64_t generation, const nlohmann::json& event)
{
    std::lock_guard lock(mMutex);
    if (generation != current(studyId)) return;
    for (const auto& [id, subscription] : mSubscriptions)
        if (subscription.studyId == studyId) subscription.sink(event);
}

void StudyProgressHub::finish(std::int64_t studyId, std::uint64_t generation, const nlohmann::json& event)
{
    std::lock_guard lock(mMutex);
    if (generation != current(studyId)) return;
    for (auto it = mSubscriptions.begin(); it != mSubscriptions.end();) {
        if (it->second.studyId != studyId) {
            ++it;
            continue;
        }
        it->second.sink(event);
        it = mSubscriptions.erase(it);
    }
    if (mFinished.emplace(studyId, event).second) mFinishedOrder.push_back(studyId);
    if (mFinishedOrder.size() > kFinishedKept) {
        mFinished.erase(mFinishedOrder.front());
        mFinishedOrder.pop_front();
    }
}

void StudyProgressHub::reopen(std::int64_t studyId)
{
    std::lock_guard lock(mMutex);
    if (mFinished.erase(studyId)) std::erase(mFinishedOrder, studyId);
    ++mGenerations[studyId];
}

std::size_t StudyProgressHub::subscriptionCount() const
{
    std::lock_guard lock(mMutex);
    return mSubscriptions.size();
}

} // namespace tlmhub::server
