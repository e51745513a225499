#include "server/auth/DownloadLinks.h"

#include "server/auth/Sodium.h"
#include "server/store/UnixTime.h"

#include <sodium.h>

#include <charconv>

namespace tlmhub::server {

namespace {

std::optional<std::int64_t> parseInt(const std::string& text)
{
    std::int64_t value = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

} // namespace

DownloadLinks::DownloadLinks(std::chrono::seconds ttl) : mTtl(ttl)
{
    ensureSodium();
    mKey.resize(crypto_auth_KEYBYTES);
    randombytes_buf(mKey.data(), mKey.size());
}

std::string DownloadLinks::mac(const std::string& target, std::int64_t userId, std::int64_t expiresAt) const
{
    const std::string message = target + '\n' + std::to_string(userId) + '\n' + std::to_string(expiresAt);
    unsigned char tag[crypto_auth_BYTES];
    crypto_auth(tag, reinterpret_cast<const unsigned char*>(message.data()), message.size(),
                reinterpret_cast<const unsigned char*>(mKey.data()));
    char hex[crypto_auth_BYTES * 2 + 1];
    sodium_bin2hex(hex, sizeof hex, tag, sizeof tag);
    return hex;
}

DownloadLinks::Link DownloadLinks::sign(const std::string& target, std::int64_t userId) const
{
    const std::int64_t expiresAt = unixNow() + mTtl.count();
    const char joiner = target.find('?') == std::string::npos ? '?' : '&';
    return {target + joiner + kParameter + "=" + std::to_string(userId) + "." + std::to_string(expiresAt) +
                "." + mac(target, userId, expiresAt),
            expiresAt};
}

std::optional<std::int64_t> DownloadLinks::verify(const std::string& targetWithLink) const
{
    // The link is the last parameter; what precedes it is exactly what was signed.
    const std::string key = std::string(kParameter) + "=";
    const auto at = targetWithLink.rfind(key);
    if (at == std::string::npos || at == 0) return std::nullopt;
    const char before = targetWithLink[at - 1];
    if ((before != '?' && before != '&') || targetWithLink.find('&', at) != std::string::npos) return std::nullopt;
    const std::string target = targetWithLink.substr(0, at - 1);
    const std::string value = targetWithLink.substr(at + key.size());
    const auto dot1 = value.find('.');
    const auto dot2 = dot1 == std::string::npos ? dot1 : value.find('.', dot1 + 1);
    if (dot2 == std::string::npos) return std::nullopt;
    const auto userId = parseInt(value.substr(0, dot1));
    const auto expiresAt = parseInt(value.substr(dot1 + 1, dot2 - dot1 - 1));
    if (!userId || !expiresAt || *expiresAt <= unixNow()) return std::nullopt;
    const std::string expected = mac(target, *userId, *expiresAt);
    const std::string given = value.substr(dot2 + 1);
    if (given.size() != expected.size() || sodium_memcmp(given.data(), expected.data(), expected.size()) != 0)
        return std::nullopt;
    return userId;
}

} // namespace tlmhub::server
