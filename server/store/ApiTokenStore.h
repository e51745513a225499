#pragma once
// Personal API tokens as stored (table api_tokens): named, long-lived, revocable Bearer tokens
// for scripts. Only the SHA-256 of a token is stored; the token itself is shown once, when it
// is created (server/auth/ApiTokens).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct ApiTokenInfo {
    std::int64_t id = 0, userId = 0;
    std::string name;
    std::int64_t createdAt = 0;                 // unix s
    std::optional<std::int64_t> expiresAt;      // unix s; none: until revoked
    std::optional<std::int64_t> lastUsedAt;     // unix s; none: never used
};

class ApiTokenStore {
public:
    virtual ~ApiTokenStore() = default;

    // A new token of `userId` with the SHA-256 (hex) of its text. Returns its id, or nullopt
    // when the user does not exist.
    virtual std::optional<std::int64_t> insert(std::int64_t userId, const std::string& name,
                                               const std::string& tokenHash, std::int64_t createdAt,
                                               std::optional<std::int64_t> expiresAt) = 0;
    // The token with this hash if it has not expired at `now`; records `now` as its last use
    // (at most once a minute, so a busy script does not write on every call).
    virtual std::optional<ApiTokenInfo> use(const std::string& tokenHash, std::int64_t now) = 0;
    // The user's tokens, newest first (expired ones too, until deleted).
    virtual std::vector<ApiTokenInfo> list(std::int64_t userId) = 0;
    virtual std::size_t count(std::int64_t userId) = 0;
    // Deletes the user's token `id`; false when the user has no such token.
    virtual bool remove(std::int64_t userId, std::int64_t id) = 0;
    // Deletes every token of the user (an account being disabled); how many there were.
    virtual std::size_t removeAll(std::int64_t userId) = 0;
};

} // namespace tlmhub::server
