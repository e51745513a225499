#pragma once
// The start of a sign-in with the authorization code flow (OpenID Connect Core §3.1.2, with
// PKCE, RFC 7636): three secrets made for this one sign-in and the address the person's browser
// is sent to. `state` ties the provider's answer to this start (no login CSRF), `nonce` ties
// the ID token to it (no replayed token), and the code verifier makes a stolen code useless to
// anyone but this server. Each is 32 random bytes, base64url.
#include "server/auth/oidc/ProviderMetadata.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tlmhub::server {

struct SignInSecrets {
    std::string state, nonce, codeVerifier;
};

SignInSecrets newSignInSecrets();

// BASE64URL(SHA-256(verifier)): the challenge of PKCE's S256 method.
std::string pkceChallenge(std::string_view codeVerifier);

// name=value&... with each part percent-encoded (application/x-www-form-urlencoded, spaces as %20).
std::string formEncode(const std::vector<std::pair<std::string, std::string>>& fields);

// The authorization endpoint with response_type=code, the client, the redirect address,
// scope "openid profile email", state, nonce and the S256 challenge.
std::string authorizationUrl(const ProviderMetadata& provider, const std::string& clientId,
                             const std::string& redirectUri, const SignInSecrets& secrets);

} // namespace tlmhub::server
