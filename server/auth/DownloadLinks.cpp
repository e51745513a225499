#include "server/auth/DownloadLinks.h"

#include "server/auth/Sodium.h"
#include "server/store/UnixTime.h"

#include <sodium.h>

#include <charconv>
#include <regex>

namespace tlmhub::server {

namespace {

std::optional<std::int64_t> parseInt(const std::string& text)
{
    std::int64_t value = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

// A session key is a BLAKE2b hash in hex (TokenService).
bool isSessionKey(const std::string& text)
{
    return text.size() == crypto_generichash_BYTES * 2 &&
           text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

} // namespace

DownloadLinks::DownloadLinks(std::chrono::seconds ttl) : mTtl(ttl)
{
    ensureSodium();
    mKey.resize(crypto_auth_KEYBYTES);
    randombytes_buf(mKey.data(), mKey.size());
}

std::string DownloadLinks::targetProblem(const std::string& target)
{
    // The GET routes whose reply is a file; the query (format, variables) is the caller's.
    static const std::regex downloads(R"(/api/v1/(jobs/\d+/results|models/\d+|models/\d+/fmu|classes/\d+/gradebook|)"
                                      R"(studies/\d+/results|studies/\d+/runs/\d+/results|handins/\d+/model))");
    const std::string path = target.substr(0, target.find('?'));
    if (std::regex_match(path, downloads)) return "";
    return "a download link opens only a download (results, a model's file, an FMU, a gradebook, a hand-in's "
           "model), not " + path.substr(0, 200);
}

std::string DownloadLinks::mac(const std::string& target, std::int64_t userId, std::int64_t expiresAt,
                               const std::string& sessionKey) const
{
    const std::string message =
        target + '\n' + std::to_string(userId) + '\n' + std::to_string(expiresAt) + '\n' + sessionKey;
    unsigned char tag[crypto_auth_BYTES];
    crypto_auth(tag, reinterpret_cast<const unsigned char*>(message.data()), message.size(),
                reinterpret_cast<const unsigned char*>(mKey.data()));
    char hex[crypto_auth_BYTES * 2 + 1];
    sodium_bin2hex(hex, sizeof hex, tag, sizeof tag);
    return hex;
}

DownloadLinks::Link DownloadLinks::sign(const std::string& target, std::int64_t userId,
                                        const std::string& sessionKey) const
{
    const std::int64_t expiresAt = unixNow() + mTtl.count();
    const char joiner = target.find('?') == std::string::npos ? '?' : '&';
    return {target + joiner + kParameter + "=" + std::to_string(userId) + "." + std::to_string(expiresAt) + "." +
                sessionKey + "." + mac(target, userId, expiresAt, sessionKey),
            expiresAt};
}

std::optional<DownloadLinks::Signer> DownloadLinks::verify(const std::string& targetWithLink) const
{
    // The link is the last parameter; what precedes it is exactly what was signed.
    const std::string key = std::string(kParameter) + "=";
    const auto at = targetWithLink.rfind(key);
    if (at == std::string::npos || at == 0) return std::nullopt;
    const char before = targetWithLink[at - 1];
    if ((before != '?' && before != '&') || targetWithLink.find('&', at) != std::string::npos) return std::nullopt;
    const std::string target = targetWithLink.substr(0, at - 1);
    const std::string value = targetWithLink.substr(at + key.size());
    // userId.expiresAt.sessionKey.mac
    std::string fields[4];
    std::size_t from = 0;
    for (int i = 0; i < 3; ++i) {
        const auto dot = value.find('.', from);
        if (dot == std::string::npos) return std::nullopt;
        fields[i] = value.substr(from, dot - from);
        from = dot + 1;
    }
    fields[3] = value.substr(from);
    const auto userId = parseInt(fields[0]);
    const auto expiresAt = parseInt(fields[1]);
    if (!userId || !expiresAt || *expiresAt <= unixNow() || !isSessionKey(fields[2])) return std::nullopt;
    const std::string expected = mac(target, *userId, *expiresAt, fields[2]);
    const std::string& given = fields[3];
    if (given.size() != expected.size() || sodium_memcmp(given.data(), expected.data(), expected.size()) != 0)
        return std::nullopt;
    return Signer{*userId, fields[2]};
}

} // namespace tlmhub::server
