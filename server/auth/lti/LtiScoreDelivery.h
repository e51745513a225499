#pragma once
// Sends the scores in the LTI outbox (LtiStore) to the platforms' grade books (Assignment and
// Grade Services 2.0, §3.4): a thread on every API node leases due scores, gets an access
// token from the platform's token endpoint with a client assertion signed by the tool's key
// (IMS Security Framework §4.1, RFC 7523; kept until shortly before it expires), and posts
// each score to its line item. A platform that answers 5xx, 401 or 429, or cannot be reached,
// gets the score again after a wait that doubles from 10 s up to an hour; after 10 attempts,
// or any other refusal, the score is given up with the reason, which teachers see.
#include "server/auth/lti/ToolKeys.h"
#include "server/auth/oidc/ProviderHttp.h"
#include "server/store/LtiStore.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace tlmhub::server {

class LtiScoreDelivery {
public:
    LtiScoreDelivery(LtiStore& outbox, const ToolKeys& keys, const ProviderHttp& http);
    ~LtiScoreDelivery();
    LtiScoreDelivery(const LtiScoreDelivery&) = delete;
    LtiScoreDelivery& operator=(const LtiScoreDelivery&) = delete;

    void start();
    void stop();
    // A score was added: look now instead of at the next poll.
    void wake();
    // Sends what is due now, on the caller's thread; how many were delivered.
    int deliverDue(std::int64_t nowUnix);

    static constexpr int kMaxAttempts = 10;
    static constexpr std::int64_t kLeaseSeconds = 60;
    // Scores leased at a time: sent within the lease even when each waits its 5 s limits.
    static constexpr std::size_t kClaimed = 4;
    static constexpr std::chrono::seconds kPoll{5};
    // The wait before attempt `attempts + 1`: 10 s doubling, at most an hour.
    static std::int64_t retryDelaySeconds(std::int64_t attempts);

private:
    // Whether the score reached the platform; else `error` and whether to try again.
    bool send(const LtiScore& score, std::string& error, bool& retry);
    // A token for the platform's grade services; "" with `error` and `retry`.
    std::string accessToken(const LtiPlatform& platform, std::string& error, bool& retry);
    void run();

    LtiStore& mOutbox;
    const ToolKeys& mKeys;
    const ProviderHttp& mHttp;
    std::mutex mTokensMutex;
    struct Token {
        std::string value;
        std::chrono::steady_clock::time_point expiresAt;
    };
    std::map<std::int64_t, Token> mTokens;   // by platform id
    std::mutex mMutex;                       // mWoken, mStopping
    std::condition_variable mWake;
    bool mWoken = false, mStopping = false;
    std::thread mThread;
};

} // namespace tlmhub::server
