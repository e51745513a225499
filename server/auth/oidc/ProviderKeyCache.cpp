#include "server/auth/oidc/ProviderKeyCache.h"

namespace tlmhub::server {

ProviderKeyCache::ProviderKeyCache(Fetch fetch, std::chrono::seconds minRefetch, std::chrono::seconds maxAge)
    : mFetch(std::move(fetch)), mMinRefetch(minRefetch), mMaxAge(maxAge)
{
}

std::shared_ptr<const JsonWebKeySet> ProviderKeyCache::keys(bool refetch, Clock::time_point now, std::string& error)
{
    std::lock_guard lock(mMutex);
    const bool stale = !mKeys || refetch || now - *mFetchedAt >= mMaxAge;
    const bool mayTry = !mTriedAt || now - *mTriedAt >= mMinRefetch;
    if (stale && mayTry) {
        mTriedAt = now;
        std::string fetchError;
        if (auto fetched = mFetch(fetchError)) {
            mKeys = std::make_shared<const JsonWebKeySet>(std::move(*fetched));
            mFetchedAt = now;
            mLastError.clear();
        } else {
            mLastError = std::move(fetchError);
        }
    }
    if (!mKeys) error = mLastError.empty() ? "the provider's keys were fetched too recently to ask again" : mLastError;
    return mKeys;
}

} // namespace tlmhub::server
