#include "server/auth/oidc/AuthorizationRequest.h"

#include "server/auth/Sodium.h"
#include "server/auth/oidc/Base64Url.h"

#include <sodium.h>

namespace tlmhub::server {

namespace {

std::string randomBase64Url()
{
    ensureSodium();
    std::string bytes(32, '\0');
    randombytes_buf(bytes.data(), bytes.size());
    return encodeBase64Url(bytes);
}

} // namespace

SignInSecrets newSignInSecrets()
{
    return {randomBase64Url(), randomBase64Url(), randomBase64Url()};
}

std::string pkceChallenge(std::string_view codeVerifier)
{
    ensureSodium();
    std::string digest(crypto_hash_sha256_BYTES, '\0');
    crypto_hash_sha256(reinterpret_cast<unsigned char*>(digest.data()),
                       reinterpret_cast<const unsigned char*>(codeVerifier.data()), codeVerifier.size());
    return encodeBase64Url(digest);
}

std::string percentEncode(std::string_view text)
{
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' ||
            c == '_' || c == '~') {
            out += ch;
        } else {
            out += '%';
            out += kHex[c >> 4];
            out += kHex[c & 0xf];
        }
    }
    return out;
}

std::string formEncode(const std::vector<std::pair<std::string, std::string>>& fields)
{
    std::string out;
    for (const auto& [name, value] : fields) {
        if (!out.empty()) out += '&';
        out += percentEncode(name) + '=' + percentEncode(value);
    }
    return out;
}

std::string authorizationUrl(const ProviderMetadata& provider, const std::string& clientId,
                             const std::string& redirectUri, const SignInSecrets& secrets)
{
    const std::string& endpoint = provider.authorizationEndpoint;
    const char separator = endpoint.find('?') == std::string::npos ? '?' : '&';
    return endpoint + separator +
           formEncode({{"response_type", "code"},
                       {"client_id", clientId},
                       {"redirect_uri", redirectUri},
                       {"scope", "openid profile email"},
                       {"state", secrets.state},
                       {"nonce", secrets.nonce},
                       {"code_challenge", pkceChallenge(secrets.codeVerifier)},
                       {"code_challenge_method", "S256"}});
}

} // namespace tlmhub::server
