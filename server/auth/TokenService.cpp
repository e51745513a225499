#include "server/auth/TokenService.h"

#include "server/auth/Sodium.h"
#include "server/store/UnixTime.h"

#include <sodium.h>

namespace tlmhub::server {

namespace {

constexpr std::size_t kLoginTokenBytes = 32;

std::string loginTokenHash(const std::string& token)
{
    ensureSodium();
    unsigned char digest[crypto_generichash_BYTES];
    crypto_generichash(digest, sizeof digest, reinterpret_cast<const unsigned char*>(token.data()),
                       token.size(), nullptr, 0);
    char hex[crypto_generichash_BYTES * 2 + 1];
    sodium_bin2hex(hex, sizeof hex, digest, sizeof digest);
    return hex;
}

} // namespace

TokenService::TokenService(SessionStore& sessions, UserStore& users, std::chrono::seconds ttl)
    : mSessions(sessions), mUsers(users), mTtl(ttl)
{
}

TokenService::Issued TokenService::issue(const User& user)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    Issued issued{randomHex(kLoginTokenBytes), now + mTtl.count()};
    mSessions.insert(loginTokenHash(issued.token), user.id, issued.expiresAt, now);
    return issued;
}

std::optional<User> TokenService::validate(const std::string& token)
{
    if (token.size() != kLoginTokenBytes * 2) return std::nullopt;
    return validateSessionKey(loginTokenHash(token));
}

std::string TokenService::sessionKey(const std::string& token) { return loginTokenHash(token); }

std::optional<User> TokenService::validateSessionKey(const std::string& key)
{
    const auto userId = mSessions.userOf(key, static_cast<std::int64_t>(unixNow()));
    if (!userId) return std::nullopt;
    auto user = mUsers.find(*userId);
    if (user && user->disabled) return std::nullopt;
    return user;
}

void TokenService::revoke(const std::string& token) { mSessions.remove(loginTokenHash(token)); }

void TokenService::revokeAllFor(std::int64_t userId) { mSessions.removeAllFor(userId); }

} // namespace tlmhub::server
