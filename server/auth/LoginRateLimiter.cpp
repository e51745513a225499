#include "server/auth/LoginRateLimiter.h"

#include <algorithm>

namespace tlmhub::server {

namespace {
// Keys are attacker-chosen (any username), so the map is swept of stale keys once it grows
// past this size instead of growing without bound.
constexpr std::size_t kSweepThreshold = 10000;
}

LoginRateLimiter::LoginRateLimiter(int maxFailures, std::chrono::seconds window)
    : LoginRateLimiter(maxFailures, window, [] { return Clock::now(); })
{
}

LoginRateLimiter::LoginRateLimiter(int maxFailures, std::chrono::seconds window, Now now)
    : mMaxFailures(maxFailures), mWindow(window), mNow(std::move(now))
{
}

bool LoginRateLimiter::allowed(const std::string& key)
{
    const Clock::time_point now = mNow();
    std::lock_guard lock(mMutex);
    auto it = mFailures.find(key);
    if (it == mFailures.end()) return true;
    dropExpired(it->second, now);
    if (it->second.empty()) {
        mFailures.erase(it);
        return true;
    }
    return static_cast<int>(it->second.size()) < mMaxFailures;
}

std::chrono::seconds LoginRateLimiter::retryAfter(const std::string& key)
{
    const Clock::time_point now = mNow();
    std::lock_guard lock(mMutex);
    auto it = mFailures.find(key);
    if (it == mFailures.end() || it->second.empty()) return std::chrono::seconds(1);
    const auto left = mWindow - (now - it->second.front());
    return std::max(std::chrono::seconds(1), std::chrono::ceil<std::chrono::seconds>(left));
}

void LoginRateLimiter::recordFailure(const std::string& key)
{
    const Clock::time_point now = mNow();
    std::lock_guard lock(mMutex);
    sweepIfLarge(now);
    auto& failures = mFailures[key];
    dropExpired(failures, now);
    failures.push_back(now);
    // Only the newest maxFailures matter for the decision.
    while (static_cast<int>(failures.size()) > mMaxFailures) failures.pop_front();
}

void LoginRateLimiter::recordSuccess(const std::string& key)
{
    std::lock_guard lock(mMutex);
    mFailures.erase(key);
}

void LoginRateLimiter::dropExpired(std::deque<Clock::time_point>& failures,
                                   Clock::time_point now) const
{
    while (!failures.empty() && now - failures.front() >= mWindow) failures.pop_front();
}

void LoginRateLimiter::sweepIfLarge(Clock::time_point now)
{
    if (mFailures.size() < kSweepThreshold) return;
    for (auto it = mFailures.begin(); it != mFailures.end();) {
        dropExpired(it->second, now);
        it = it->second.empty() ? mFailures.erase(it) : std::next(it);
    }
}

} // namespace tlmhub::server
