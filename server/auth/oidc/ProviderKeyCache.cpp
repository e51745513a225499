#include "server/auth/oidc/ProviderKeyCache.h"

namespace tlmhub::server {

ProviderKeyCache::ProviderKeyCache(Fetch fetch, std::chrono::seconds minRefetch, std::chrono::seconds maxAge)
    : mFetch(std::move(fetch)), mMinRefetch(minRefetch), mMaxAge(maxAge)
{
}

std::shared_ptr<const JsonWebKeySet> ProviderKeyCache::keys(bool refetch, Clock::time_point now, std::string& error)
{
    std::lock_guard lock(mMutex);
    // A key the set lacks is asked for at once after the set's own fetch (a rotation just
    // published), but made-up key ids make at most one fetch per mMinRefetch; so do fetches
    // that fail.
    const auto since = [&](const std::optional<Clock::time_point>& at) { return !at || now - *at >= mMinRefetch; };
    const bool stale = !mKeys || now - *mFetchedAt >= mMaxAge;
    if ((stale && since(mTriedAt)) || (mKeys && refetch && !stale && since(mRefetchTriedAt))) {
        if (!stale) mRefetchTriedAt = now;
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
