#pragma once
// Login sessions (table sessions): the hash of a bearer token, its user and when it expires.
// Tokens themselves are made and hashed by server/auth/TokenService.
#include <cstdint>
#include <optional>
#include <string>

namespace tlmhub::server {

class SessionStore {
public:
    virtual ~SessionStore() = default;

    // Adds a session and, in the same transaction, deletes every session expired at `now`
    // (so the table stays small when clients never log out). Works on a full disk too: logging
    // in is how an owner gets to delete what fills it.
    virtual void insert(const std::string& tokenHash, std::int64_t userId, std::int64_t expiresAt,
                        std::int64_t now) = 0;
    // The session's user id; nullopt when there is no such session or it expired at `now`
    // (an expired one is deleted on the way).
    virtual std::optional<std::int64_t> userOf(const std::string& tokenHash, std::int64_t now) = 0;
    virtual void remove(const std::string& tokenHash) = 0;
    virtual void removeAllFor(std::int64_t userId) = 0;
};

} // namespace tlmhub::server
