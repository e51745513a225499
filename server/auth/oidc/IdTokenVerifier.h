#pragma once
// Checking an ID token (OpenID Connect Core 1.0 §3.1.3.7) that came back from the provider's
// token endpoint: its signature against the provider's published keys, then who issued it,
// for whom, when, and for which sign-in (the nonce). Every failure has a stable code, and
// the message names the claim without echoing the token.
#include "server/auth/oidc/ProviderKeyCache.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

namespace tlmhub::server {

struct IdTokenExpectations {
    std::string issuer;     // the provider's issuer, exactly
    std::string clientId;   // the only audience accepted; `azp`, when given, must be it
    std::string nonce;      // the one this sign-in sent (its state is used once)
    std::int64_t now = 0;   // unix seconds
    std::int64_t skewSeconds = 120;     // clock difference allowed on exp, iat and nbf
    std::int64_t maxAgeSeconds = 600;   // a token issued longer ago than this is not taken
};

struct IdToken {
    std::string subject;    // `sub`: with the issuer, who the person is
    nlohmann::json claims;  // all of them (names, groups for roles)
};

struct IdTokenError {
    // malformed, unsupported_algorithm, keys_unavailable, unknown_key, bad_signature,
    // wrong_issuer, wrong_audience, wrong_azp, expired, not_yet_valid, issued_in_future,
    // too_old, wrong_nonce, no_subject
    std::string code;
    std::string message;
};

// The largest token taken (providers' tokens are a few kilobytes, with groups tens).
inline constexpr std::size_t kMaxIdTokenBytes = 64 * 1024;

std::variant<IdToken, IdTokenError> verifyIdToken(std::string_view token, ProviderKeyCache& keys,
                                                  const IdTokenExpectations& expected,
                                                  ProviderKeyCache::Clock::time_point steadyNow = ProviderKeyCache::Clock::now());

} // namespace tlmhub::server
