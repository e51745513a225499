#include "server/auth/oidc/ProviderMetadata.h"

#include "server/auth/oidc/JsonMembers.h"
#include "server/auth/oidc/JwsSignature.h"

#include <algorithm>
#include <vector>

namespace tlmhub::server {

namespace {

// The member's strings; `fallback` when the document leaves it out (the specification's default).
std::vector<std::string> listMember(const nlohmann::json& object, const char* name, std::vector<std::string> fallback)
{
    const auto it = object.find(name);
    if (it == object.end()) return fallback;
    std::vector<std::string> values;
    if (it->is_array())
        for (const nlohmann::json& value : *it)
            if (value.is_string()) values.push_back(value.get<std::string>());
    return values;
}

bool listHas(const std::vector<std::string>& values, const std::string& value)
{
    return std::ranges::find(values, value) != values.end();
}

// https://host[...]: no credentials in it, no fragment (RFC 6749 §3.1).
bool isHttpsEndpoint(const std::string& url)
{
    constexpr std::string_view scheme = "https://";
    if (!url.starts_with(scheme) || url.size() == scheme.size() || url.find('#') != std::string::npos) return false;
    const std::string authority = url.substr(scheme.size(), url.find('/', scheme.size()) - scheme.size());
    return !authority.empty() && authority.find('@') == std::string::npos &&
           std::ranges::none_of(url, [](unsigned char c) { return c <= ' ' || c == 0x7f; });
}

} // namespace

std::string discoveryUrl(const std::string& issuer)
{
    std::string base = issuer;
    if (base.ends_with('/')) base.pop_back();
    return base + "/.well-known/openid-configuration";
}

std::optional<ProviderMetadata> parseProviderMetadata(const nlohmann::json& document, const std::string& issuer,
                                                      std::string& error)
{
    if (!document.is_object()) {
        error = "the discovery document is not a JSON object";
        return std::nullopt;
    }
    ProviderMetadata metadata{stringMember(document, "issuer"), stringMember(document, "authorization_endpoint"),
                              stringMember(document, "token_endpoint"), stringMember(document, "jwks_uri"), ""};
    if (metadata.issuer != issuer) {
        error = "the discovery document names another issuer than " + issuer;
        return std::nullopt;
    }
    for (const auto& [name, url] : {std::pair{"authorization_endpoint", metadata.authorizationEndpoint},
                                    std::pair{"token_endpoint", metadata.tokenEndpoint},
                                    std::pair{"jwks_uri", metadata.jwksUri}})
        if (!isHttpsEndpoint(url)) {
            error = std::string("the discovery document's ") + name + " is not an https URL";
            return std::nullopt;
        }
    if (!listHas(listMember(document, "response_types_supported", {}), "code")) {
        error = "the provider does not offer the authorization code flow (response_types_supported)";
        return std::nullopt;
    }
    const auto challenges = listMember(document, "code_challenge_methods_supported", {"S256"});
    if (!listHas(challenges, "S256")) {
        error = "the provider does not offer PKCE with S256 (code_challenge_methods_supported)";
        return std::nullopt;
    }
    const auto algorithms = listMember(document, "id_token_signing_alg_values_supported", {"RS256"});
    if (std::ranges::none_of(algorithms, isSupportedJwsAlgorithm)) {
        error = "the provider signs ID tokens with no algorithm this server checks (id_token_signing_alg_values_supported)";
        return std::nullopt;
    }
    const auto methods = listMember(document, "token_endpoint_auth_methods_supported", {"client_secret_basic"});
    if (listHas(methods, "client_secret_basic")) metadata.tokenAuthMethod = "client_secret_basic";
    else if (listHas(methods, "client_secret_post")) metadata.tokenAuthMethod = "client_secret_post";
    else {
        error = "the provider takes a client secret neither by client_secret_basic nor by client_secret_post";
        return std::nullopt;
    }
    return metadata;
}

} // namespace tlmhub::server
