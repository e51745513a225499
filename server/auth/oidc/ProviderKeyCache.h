#pragma once
// A provider's key set as this server last fetched it. A token signed with a key the set
// lacks means the provider rotated its keys: the set is fetched again at once, but for such
// tokens at most once per `minRefetch`, so tokens with made-up key ids cannot make the server
// hammer the provider (nor can a provider that cannot be reached: its fetches too wait).
// A set older than `maxAge` is fetched again at its next use, so a key the provider withdrew
// stops being trusted; when that fetch fails the old set is kept until it succeeds.
#include "server/auth/oidc/JsonWebKeySet.h"

#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace tlmhub::server {

class ProviderKeyCache {
public:
    using Clock = std::chrono::steady_clock;
    // Fetches and parses the set (bounded in time and size by the caller); nullopt with `error`.
    using Fetch = std::function<std::optional<JsonWebKeySet>(std::string& error)>;

    explicit ProviderKeyCache(Fetch fetch, std::chrono::seconds minRefetch = std::chrono::seconds(60),
                              std::chrono::seconds maxAge = std::chrono::hours(1));

    // The set to check a token with. `refetch`: the last set lacked the token's key. Null with
    // `error` when there is none (the first fetch failed).
    std::shared_ptr<const JsonWebKeySet> keys(bool refetch, Clock::time_point now, std::string& error);

private:
    Fetch mFetch;
    const std::chrono::seconds mMinRefetch, mMaxAge;
    std::mutex mMutex;   // one fetch at a time; the members below
    std::shared_ptr<const JsonWebKeySet> mKeys;
    std::optional<Clock::time_point> mFetchedAt, mTriedAt;
    std::optional<Clock::time_point> mRefetchTriedAt;   // the last fetch for a key the set lacked
    std::string mLastError;
};

} // namespace tlmhub::server
