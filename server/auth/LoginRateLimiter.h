#pragma once
// Slows password guessing: after `maxFailures` failed logins for one key (a user name at a
// client address, or an address) within a sliding `window`, further attempts are refused until
// the oldest failure leaves the window. In memory only; a restart forgets, which is acceptable
// for this purpose.
#include <chrono>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <unordered_map>

namespace tlmhub::server {

class LoginRateLimiter {
public:
    using Clock = std::chrono::steady_clock;
    using Now = std::function<Clock::time_point()>;

    LoginRateLimiter(int maxFailures, std::chrono::seconds window);
    // For tests: a clock that can be moved by hand.
    LoginRateLimiter(int maxFailures, std::chrono::seconds window, Now now);

    // False while `key` has maxFailures failures inside the window.
    bool allowed(const std::string& key);
    // When `key` is allowed again: until its oldest failure leaves the window (at least 1 s).
    std::chrono::seconds retryAfter(const std::string& key);
    void recordFailure(const std::string& key);
    // A successful login clears the key's failures.
    void recordSuccess(const std::string& key);

private:
    void dropExpired(std::deque<Clock::time_point>& failures, Clock::time_point now) const;
    void sweepIfLarge(Clock::time_point now);

    const int mMaxFailures;
    const std::chrono::seconds mWindow;
    Now mNow;
    std::mutex mMutex;
    std::unordered_map<std::string, std::deque<Clock::time_point>> mFailures;
};

} // namespace tlmhub::server
