#pragma once
// What an OpenID provider says about itself at `{issuer}/.well-known/openid-configuration`
// (OpenID Connect Discovery 1.0 §3-4): where to send the person, where to exchange the code,
// where its keys are. Taken only when it names the configured issuer exactly (§4.3), every
// endpoint is https, and it can do what this server asks: the code flow with PKCE S256 and
// ID tokens signed by an algorithm this server checks.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace tlmhub::server {

struct ProviderMetadata {
    std::string issuer;
    std::string authorizationEndpoint, tokenEndpoint, jwksUri;
    // How the token endpoint takes the client's secret: client_secret_basic (the default of
    // the specification) or client_secret_post, when only that one is offered.
    std::string tokenAuthMethod;
};

// The discovery document's address for `issuer`.
std::string discoveryUrl(const std::string& issuer);

// nullopt with `error` naming the member that is wrong.
std::optional<ProviderMetadata> parseProviderMetadata(const nlohmann::json& document, const std::string& issuer,
                                                      std::string& error);

} // namespace tlmhub::server
