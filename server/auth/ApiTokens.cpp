#include "server/auth/ApiTokens.h"

#include "core/Sha256.h"
#include "server/auth/Sodium.h"
#include "server/store/ModelName.h"
#include "server/store/UnixTime.h"

#include <sodium.h>

#include <algorithm>

namespace tlmhub::server {

namespace {

constexpr std::size_t kTokenBytes = 32;
// base64url of 32 bytes without padding: ceil(32 * 4 / 3).
constexpr std::size_t kEncodedLength = 43;
constexpr std::int64_t kSecondsPerDay = 86400;

std::string tokenHash(const std::string& token)
{
    Sha256 sha;
    sha.update(token);
    return sha.hexDigest();
}

std::string newToken()
{
    ensureSodium();
    unsigned char bytes[kTokenBytes];
    randombytes_buf(bytes, sizeof bytes);
    const int variant = sodium_base64_VARIANT_URLSAFE_NO_PADDING;
    std::string encoded(sodium_base64_encoded_len(sizeof bytes, variant), '\0');
    sodium_bin2base64(encoded.data(), encoded.size(), bytes, sizeof bytes, variant);
    encoded.resize(kEncodedLength);   // drops the terminating NUL
    return ApiTokens::kPrefix + encoded;
}

// UTF-8 code points, as JSON Schema's maxLength counts (continuation bytes are 10xxxxxx).
std::size_t characterCount(const std::string& text)
{
    return static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

} // namespace

ApiTokens::ApiTokens(ApiTokenStore& store, UserStore& users) : mStore(store), mUsers(users) {}

bool ApiTokens::isApiToken(const std::string& text)
{
    return text.rfind(kPrefix, 0) == 0;
}

ApiTokens::Creation ApiTokens::create(const User& owner, const std::string& name,
                                      std::optional<std::int64_t> expiresInDays)
{
    const std::size_t length = characterCount(name);
    if (length < 1 || length > kMaxNameLength)
        return {std::nullopt, "bad_request", "a token's name has 1 to " + std::to_string(kMaxNameLength) + " characters"};
    // Names are listed in the app and in scripts' output: no line breaks or reordering.
    if (const std::string problem = nameCharacterProblem(name); !problem.empty())
        return {std::nullopt, "bad_request", "a token's name: " + problem};
    if (expiresInDays && (*expiresInDays < 1 || *expiresInDays > kMaxExpiryDays))
        return {std::nullopt, "bad_request", "expires_in_days is 1 to " + std::to_string(kMaxExpiryDays)};
    // Two creations at once may both pass this check: the limit bounds a user's tokens, it is
    // not a quota that must hold to the unit.
    if (mStore.count(owner.id) >= kMaxPerUser)
        return {std::nullopt, "limit_exceeded",
                "at most " + std::to_string(kMaxPerUser) + " API tokens per user (a fixed limit); delete one first"};
    Created created{newToken(), {}};
    created.info.userId = owner.id;
    created.info.name = name;
    created.info.createdAt = static_cast<std::int64_t>(unixNow());
    if (expiresInDays) created.info.expiresAt = created.info.createdAt + *expiresInDays * kSecondsPerDay;
    const auto id = mStore.insert(owner.id, name, tokenHash(created.token), created.info.createdAt,
                                  created.info.expiresAt);
    if (!id) return {std::nullopt, "bad_request", "no such user"};
    created.info.id = *id;
    return {std::move(created), "", ""};
}

std::vector<ApiTokenInfo> ApiTokens::list(const User& owner)
{
    return mStore.list(owner.id);
}

bool ApiTokens::revoke(const User& owner, std::int64_t id)
{
    return mStore.remove(owner.id, id);
}

void ApiTokens::revokeAllFor(std::int64_t userId)
{
    mStore.removeAll(userId);
}

std::optional<User> ApiTokens::authenticate(const std::string& token)
{
    if (!isApiToken(token) || token.size() != std::string(kPrefix).size() + kEncodedLength) return std::nullopt;
    const auto stored = mStore.use(tokenHash(token), static_cast<std::int64_t>(unixNow()));
    if (!stored) return std::nullopt;
    auto user = mUsers.find(stored->userId);
    if (user && user->disabled) return std::nullopt;
    return user;
}

} // namespace tlmhub::server
