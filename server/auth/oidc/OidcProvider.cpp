#include "server/auth/oidc/OidcProvider.h"

#include "server/auth/Sodium.h"
#include "server/auth/oidc/JsonMembers.h"

#include "net/Url.h"

#include <sodium.h>

namespace tlmhub::server {

namespace {

constexpr auto kMetadataAge = std::chrono::hours(1);
constexpr auto kRetryAfterFailure = std::chrono::minutes(1);

// HTTP Basic credentials of a client (RFC 6749 §2.3.1: id and secret form-encoded first).
std::string basicCredentials(const std::string& clientId, const std::string& secret)
{
    ensureSodium();
    const std::string pair = net::percentEncode(clientId) + ':' + net::percentEncode(secret);
    constexpr int variant = sodium_base64_VARIANT_ORIGINAL;
    std::string text(sodium_base64_ENCODED_LEN(pair.size(), variant), '\0');
    sodium_bin2base64(text.data(), text.size(), reinterpret_cast<const unsigned char*>(pair.data()), pair.size(),
                      variant);
    text.resize(text.size() - 1);
    return "Basic " + text;
}

} // namespace

OidcProvider::OidcProvider(OidcProviderSettings settings, const ProviderHttp& http)
    : mSettings(std::move(settings)), mHttp(http), mKeys([this](std::string& error) -> std::optional<JsonWebKeySet> {
          const auto provider = metadata(error);
          if (!provider) return std::nullopt;
          return mHttp.getKeySet(provider->jwksUri, error);
      })
{
}

std::optional<ProviderMetadata> OidcProvider::metadata(std::string& error)
{
    std::lock_guard lock(mMutex);
    const auto now = Clock::now();
    const bool fresh = mMetadata && now - *mFetchedAt < kMetadataAge;
    // Tried at most once a minute: a provider that is down is not asked at every sign-in.
    if (!fresh && (!mTriedAt || now - *mTriedAt >= kRetryAfterFailure)) {
        mTriedAt = now;
        std::string fetchError;
        const auto reply = mHttp.getJson(discoveryUrl(mSettings.issuer), fetchError);
        std::optional<ProviderMetadata> parsed;
        if (reply && reply->status == 200) parsed = parseProviderMetadata(reply->body, mSettings.issuer, fetchError);
        else if (reply) fetchError = "the discovery document answered " + std::to_string(reply->status);
        if (parsed) {
            mMetadata = std::move(parsed);
            mFetchedAt = now;
        } else {
            mLastError = std::move(fetchError);
        }
    }
    if (!mMetadata) error = mLastError;
    return mMetadata;
}

std::optional<std::string> OidcProvider::authorizationUrl(const SignInSecrets& secrets, const std::string& redirectUri,
                                                          std::string& error)
{
    const auto provider = metadata(error);
    if (!provider) return std::nullopt;
    return server::authorizationUrl(*provider, mSettings.clientId, redirectUri, secrets);
}

std::variant<IdToken, IdTokenError> OidcProvider::finish(const std::string& code, const std::string& codeVerifier,
                                                         const std::string& nonce, const std::string& redirectUri,
                                                         std::int64_t nowUnix)
{
    std::string error;
    const auto provider = metadata(error);
    if (!provider) return IdTokenError{"provider_unavailable", error};
    std::vector<std::pair<std::string, std::string>> form = {{"grant_type", "authorization_code"},
                                                             {"code", code},
                                                             {"redirect_uri", redirectUri},
                                                             {"code_verifier", codeVerifier}};
    std::vector<std::pair<std::string, std::string>> headers;
    if (provider->tokenAuthMethod == "client_secret_post") {
        form.emplace_back("client_id", mSettings.clientId);
        form.emplace_back("client_secret", mSettings.clientSecret);
    } else {
        headers.emplace_back("Authorization", basicCredentials(mSettings.clientId, mSettings.clientSecret));
    }
    const auto reply = mHttp.postForm(provider->tokenEndpoint, formEncode(form), headers, error);
    if (!reply) return IdTokenError{"provider_unavailable", error};
    if (reply->status != 200) {
        // The provider's own code (invalid_grant: a used or expired code, a wrong verifier).
        const std::string reason = stringMember(reply->body, "error");
        return IdTokenError{"token_refused", "the provider refused the code (" + reason.substr(0, 80) + ")"};
    }
    const std::string idToken = stringMember(reply->body, "id_token");
    if (idToken.empty()) return IdTokenError{"malformed", "the provider's answer has no ID token"};
    return verifyIdToken(idToken, mKeys, {mSettings.issuer, mSettings.clientId, nonce, nowUnix});
}

} // namespace tlmhub::server
