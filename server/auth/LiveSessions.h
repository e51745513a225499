#pragma once
// The open WebSocket connections and the token each was opened with (a login's or an API
// token), so a connection ends when its token does: logout, password change, expiry, a
// revoked API token, or a disabled account. Checked on a thread of its own every `period`
// (expiry needs a clock anyway) and at once by the routes that end tokens, so a socket closes
// well within a second.
#include "server/http/HttpApplication.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace tlmhub::server {

class LiveSessions {
public:
    // Whether `token` still lets its user in (read fresh: a disabled account's does not).
    using TokenCheck = std::function<bool(const std::string& token)>;
    LiveSessions(TokenCheck stillValid, std::chrono::milliseconds period);
    ~LiveSessions();
    LiveSessions(const LiveSessions&) = delete;
    LiveSessions& operator=(const LiveSessions&) = delete;

    std::uint64_t add(const std::string& token, std::int64_t userId, std::shared_ptr<WebSocketSender> sender);
    void remove(std::uint64_t id);
    // Closes every connection whose token no longer validates; returns how many.
    int sweep();
    // Closes every connection of one user (e.g. after a role change: it reconnects with the
    // new role) ; returns how many.
    int closeAllOf(std::int64_t userId, const std::string& reason);

private:
    struct Entry {
        std::string token;
        std::int64_t userId;
        std::weak_ptr<WebSocketSender> sender;
    };
    void loop();

    const TokenCheck mStillValid;
    const std::chrono::milliseconds mPeriod;
    std::mutex mMutex;
    std::map<std::uint64_t, Entry> mEntries;
    std::uint64_t mNextId = 1;
    std::condition_variable mWake;
    bool mStopping = false;
    std::thread mThread;
};

} // namespace tlmhub::server
