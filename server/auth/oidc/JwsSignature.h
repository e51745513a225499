#pragma once
// Checking a JSON Web Signature (RFC 7515) made with one of the asymmetric algorithms an
// OpenID provider signs ID tokens with: RS256/384/512, PS256/384/512, ES256 and ES384. HMAC
// and "none" are never accepted: a token is trusted only when the provider's public key
// checks it.
#include "server/auth/oidc/JsonWebKeySet.h"

#include <string>
#include <string_view>

namespace tlmhub::server {

bool isSupportedJwsAlgorithm(const std::string& alg);

// Whether `signature` (the decoded third part of the token) signs `signingInput` (the token's
// first two parts with the dot between them) with `key` by `alg`.
bool verifyJwsSignature(const JsonWebKey& key, const std::string& alg, std::string_view signingInput,
                        std::string_view signature);

} // namespace tlmhub::server
