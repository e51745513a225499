#pragma once
// One OpenID provider the administrator configured (--oidc-issuer ...): where a sign-in sends
// the person, and how its answer becomes a checked ID token: the code exchanged at the token
// endpoint with the PKCE verifier and the client's secret, then the token checked
// (IdTokenVerifier.h). The discovery document is fetched at the first sign-in and kept for an
// hour; a failed fetch is tried again at most once a minute.
#include "server/auth/oidc/AuthorizationRequest.h"
#include "server/auth/oidc/IdTokenVerifier.h"
#include "server/auth/oidc/ProviderHttp.h"
#include "server/auth/oidc/ProviderMetadata.h"

#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <variant>

namespace tlmhub::server {

struct OidcProviderSettings {
    std::string name;          // in the sign-in's addresses (/auth/oidc/{name}/...)
    std::string displayName;   // the button's "Sign in with {displayName}"
    std::string issuer, clientId, clientSecret;
};

class OidcProvider {
public:
    OidcProvider(OidcProviderSettings settings, const ProviderHttp& http);

    const OidcProviderSettings& settings() const { return mSettings; }

    // The provider's authorization address for this sign-in; nullopt with `error` when the
    // provider cannot be asked (its discovery document unreachable or unfit).
    std::optional<std::string> authorizationUrl(const SignInSecrets& secrets, const std::string& redirectUri,
                                                std::string& error);
    // The code of the provider's answer exchanged for tokens and the ID token checked. Codes
    // besides IdTokenError's: provider_unavailable, token_refused.
    std::variant<IdToken, IdTokenError> finish(const std::string& code, const std::string& codeVerifier,
                                               const std::string& nonce, const std::string& redirectUri,
                                               std::int64_t nowUnix);

private:
    using Clock = std::chrono::steady_clock;
    std::optional<ProviderMetadata> metadata(std::string& error);

    const OidcProviderSettings mSettings;
    const ProviderHttp& mHttp;
    std::mutex mMutex;   // the discovery document
    std::optional<ProviderMetadata> mMetadata;
    std::optional<Clock::time_point> mFetchedAt, mTriedAt;
    std::string mLastError;
    ProviderKeyCache mKeys;
};

} // namespace tlmhub::server
