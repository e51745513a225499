#include "server/auth/oidc/AuthorizationRequest.h"

#include "server/auth/Sodium.h"
#include "server/auth/oidc/Base64Url.h"

#include "net/Url.h"

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

std::string formEncode(const std::vector<std::pair<std::string, std::string>>& fields)
{
    std::string out;
    for (const auto& [name, value] : fields) {
        if (!out.empty()) out += '&';
        out += net::percentEncode(name) + '=' + net::percentEncode(value);
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
