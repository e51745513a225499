#pragma once
// Personal API tokens: named, long-lived Bearer tokens for scripts (docs/studies.md, "API
// tokens"). A token is `tlmh_` and 43 characters of base64url (32 random bytes); only its
// SHA-256 is stored (ApiTokenStore), so a copy of the database does not hand out working
// tokens. The prefix tells them from login tokens (64 hex digits) without a database lookup.
#include "server/auth/User.h"
#include "server/store/ApiTokenStore.h"
#include "server/store/UserStore.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

class ApiTokens {
public:
    static constexpr const char* kPrefix = "tlmh_";
    static constexpr std::size_t kMaxPerUser = 50;
    static constexpr std::size_t kMaxNameLength = 100;   // characters (UTF-8 code points)
    static constexpr std::int64_t kMaxExpiryDays = 3650;

    ApiTokens(ApiTokenStore& store, UserStore& users);

    // Whether `text` is meant as an API token (it has the prefix), valid or not.
    static bool isApiToken(const std::string& text);

    struct Created {
        std::string token;   // shown once
        ApiTokenInfo info;
    };
    struct Creation {
        std::optional<Created> created;
        std::string code, message;   // when not created: bad_request or limit_exceeded
    };
    // A new token of `owner` named `name`, expiring `expiresInDays` days from now (never when
    // absent).
    Creation create(const User& owner, const std::string& name, std::optional<std::int64_t> expiresInDays);
    std::vector<ApiTokenInfo> list(const User& owner);
    // False when `owner` has no token `id` (another user's included).
    bool revoke(const User& owner, std::int64_t id);
    // Every token of the user: an account being disabled (enabling it again revives none).
    void revokeAllFor(std::int64_t userId);
    // The token's user, read fresh; nullopt when the token is unknown, revoked or expired, or
    // the account is disabled. Records the use (ApiTokenStore::use).
    std::optional<User> authenticate(const std::string& token);

private:
    ApiTokenStore& mStore;
    UserStore& mUsers;
};

} // namespace tlmhub::server
