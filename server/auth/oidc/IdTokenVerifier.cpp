#include "server/auth/oidc/IdTokenVerifier.h"

#include "server/auth/oidc/Base64Url.h"
#include "server/auth/oidc/JsonMembers.h"
#include "server/auth/oidc/JwsSignature.h"

#include <openssl/crypto.h>

#include <optional>

namespace tlmhub::server {

namespace {

std::optional<std::int64_t> timeClaim(const nlohmann::json& claims, const char* name)
{
    const auto it = claims.find(name);
    if (it == claims.end() || !it->is_number()) return std::nullopt;
    const double seconds = it->get<double>();
    if (!(seconds > -1e15 && seconds < 1e15)) return std::nullopt;
    return std::int64_t(seconds);
}

// A part of the compact form, decoded and parsed as a JSON object.
std::optional<nlohmann::json> jsonPart(std::string_view part)
{
    const auto bytes = decodeBase64Url(part);
    if (!bytes) return std::nullopt;
    nlohmann::json json = nlohmann::json::parse(*bytes, nullptr, false);
    if (!json.is_object()) return std::nullopt;
    return json;
}

bool equalInConstantTime(const std::string& a, const std::string& b)
{
    return a.size() == b.size() && CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

IdTokenError refused(std::string code, std::string message)
{
    return {std::move(code), std::move(message)};
}

// The claims' checks, once the signature holds.
std::optional<IdTokenError> claimsProblem(const nlohmann::json& claims, const IdTokenExpectations& expected)
{
    if (stringMember(claims, "iss") != expected.issuer)
        return refused("wrong_issuer", "the ID token was not issued by " + expected.issuer);
    const auto aud = claims.find("aud");
    const bool forUs = aud != claims.end() &&
                       ((aud->is_string() && aud->get<std::string>() == expected.clientId) ||
                        (aud->is_array() && aud->size() == 1 && (*aud)[0] == expected.clientId));
    if (!forUs) return refused("wrong_audience", "the ID token is not for this server's client id alone (aud)");
    if (claims.contains("azp") && stringMember(claims, "azp") != expected.clientId)
        return refused("wrong_azp", "the ID token was given to another client (azp)");
    const auto exp = timeClaim(claims, "exp");
    const auto iat = timeClaim(claims, "iat");
    if (!exp || !iat) return refused("malformed", "the ID token lacks exp or iat");
    if (expected.now >= *exp + expected.skewSeconds) return refused("expired", "the ID token has expired (exp)");
    if (*iat > expected.now + expected.skewSeconds)
        return refused("issued_in_future", "the ID token was issued in the future (iat): check the clocks");
    if (expected.now - *iat > expected.maxAgeSeconds + expected.skewSeconds)
        return refused("too_old", "the ID token was issued too long ago (iat)");
    if (claims.contains("nbf")) {
        const auto nbf = timeClaim(claims, "nbf");
        if (!nbf || *nbf > expected.now + expected.skewSeconds)
            return refused("not_yet_valid", "the ID token is not valid yet (nbf)");
    }
    if (expected.nonce.empty() || !equalInConstantTime(stringMember(claims, "nonce"), expected.nonce))
        return refused("wrong_nonce", "the ID token belongs to another sign-in (nonce)");
    const std::string subject = stringMember(claims, "sub");
    if (subject.empty() || subject.size() > 255) return refused("no_subject", "the ID token names nobody (sub)");
    return std::nullopt;
}

} // namespace

std::variant<IdToken, IdTokenError> verifyIdToken(std::string_view token, ProviderKeyCache& keys,
                                                  const IdTokenExpectations& expected,
                                                  ProviderKeyCache::Clock::time_point steadyNow)
{
    if (token.size() > kMaxIdTokenBytes) return refused("malformed", "the ID token is larger than 64 KiB");
    const std::size_t first = token.find('.');
    const std::size_t second = first == std::string_view::npos ? first : token.find('.', first + 1);
    if (second == std::string_view::npos || token.find('.', second + 1) != std::string_view::npos)
        return refused("malformed", "the ID token is not a signed JWT in compact form (three parts)");
    const auto header = jsonPart(token.substr(0, first));
    auto claims = jsonPart(token.substr(first + 1, second - first - 1));
    const auto signature = decodeBase64Url(token.substr(second + 1));
    if (!header || !claims || !signature) return refused("malformed", "a part of the ID token is not base64url JSON");

    const std::string alg = stringMember(*header, "alg");
    if (!isSupportedJwsAlgorithm(alg))
        return refused("unsupported_algorithm", "the ID token is signed with \"" + alg.substr(0, 20) +
                                                    "\"; accepted: RS256/384/512, PS256/384/512, ES256, ES384");
    if (header->contains("crit")) return refused("malformed", "the ID token has critical header extensions (crit)");
    const std::string kid = stringMember(*header, "kid");
    std::string keyError;
    const JsonWebKey* key = nullptr;
    std::shared_ptr<const JsonWebKeySet> set = keys.keys(false, steadyNow, keyError);
    if (set) key = set->find(kid, alg);
    if (!key) {   // the provider may have rotated its keys since they were fetched
        set = keys.keys(true, steadyNow, keyError);
        if (set) key = set->find(kid, alg);
    }
    if (!set) return refused("keys_unavailable", "the provider's keys cannot be fetched: " + keyError);
    if (!key) return refused("unknown_key", "the ID token is signed with a key the provider does not publish");
    const std::string_view signingInput = token.substr(0, second);
    if (!verifyJwsSignature(*key, alg, signingInput, *signature))
        return refused("bad_signature", "the ID token's signature does not hold");
    if (auto problem = claimsProblem(*claims, expected)) return std::move(*problem);
    return IdToken{stringMember(*claims, "sub"), std::move(*claims)};
}

} // namespace tlmhub::server
