#pragma once
// Login sessions as bearer tokens. A token is 32 random bytes (hex); only its BLAKE2b hash
// (crypto_generichash) is stored (SessionStore), so a copy of the database does not hand out
// live sessions. Tokens expire `ttl` after issue and can be revoked (logout).
#include "server/auth/User.h"
#include "server/store/SessionStore.h"
#include "server/store/UserStore.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace tlmhub::server {

class TokenService {
public:
    TokenService(SessionStore& sessions, UserStore& users, std::chrono::seconds ttl);

    struct Issued {
        std::string token;
        std::int64_t expiresAt;   // unix seconds
    };

    Issued issue(const User& user);
    // The token's user, read fresh (a changed role applies at once); nullopt when unknown,
    // revoked or expired (an expired row is deleted on the way), or the account is disabled.
    std::optional<User> validate(const std::string& token);
    // What the store keys a login token's session by (its hash): a download link names its
    // login by it, and ends with it.
    static std::string sessionKey(const std::string& token);
    // validate() for a session named by its key.
    std::optional<User> validateSessionKey(const std::string& key);
    void revoke(const std::string& token);
    // Ends every session of one user, e.g. after a password change.
    void revokeAllFor(std::int64_t userId);

private:
    SessionStore& mSessions;
    UserStore& mUsers;
    std::chrono::seconds mTtl;
};

} // namespace tlmhub::server
