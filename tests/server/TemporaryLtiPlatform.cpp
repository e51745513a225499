#include "TemporaryLtiPlatform.h"

#include "net/HttpClient.h"

#include <stdexcept>

namespace tlmhub::test {

TemporaryLtiPlatform::TemporaryLtiPlatform(const std::string& toolUrl)
    : mPeer("lti-platform", "platform.mjs", "jose",
            {{"clientId", kClientId},
             {"deploymentId", kDeploymentId},
             {"tool",
              {{"loginUrl", toolUrl + "/api/v1/lti/login"},
               {"launchUrl", toolUrl + "/api/v1/lti/launch"},
               {"jwksUrl", toolUrl + "/api/v1/lti/jwks"}}}})
{
}

nlohmann::json TemporaryLtiPlatform::registration() const
{
    return {{"name", "Test platform"},          {"issuer", issuer()},
            {"client_id", kClientId},           {"auth_url", issuer() + "/auth"},
            {"token_url", issuer() + "/token"}, {"jwks_url", issuer() + "/jwks"},
            {"deployment_ids", {kDeploymentId}}};
}

nlohmann::json TemporaryLtiPlatform::control(const std::string& path, const nlohmann::json& body) const
{
    std::string error;
    const auto server = net::parseUrl(issuer(), error);
    net::HttpRequest request;
    request.method = body.is_null() ? net::HttpMethod::Get : net::HttpMethod::Post;
    request.target = path;
    if (!body.is_null()) {
        request.body = body.dump();
        request.contentType = "application/json";
    }
    const net::HttpResponse response = net::HttpClient(*server, {}, caFile()).send(request);
    if (response.status != 200)
        throw std::runtime_error("TemporaryLtiPlatform: " + path + " answered " + std::to_string(response.status) + ": " +
                                 response.body.substr(0, 500));
    return nlohmann::json::parse(response.body);
}

nlohmann::json TemporaryLtiPlatform::authenticate(const std::string& authenticationUrl) const
{
    std::string error;
    const auto server = net::parseUrl(issuer(), error);
    if (!authenticationUrl.starts_with(issuer() + "/"))
        throw std::runtime_error("TemporaryLtiPlatform: not this platform's address: " + authenticationUrl);
    net::HttpRequest request;
    request.target = authenticationUrl.substr(issuer().size());
    request.headers.emplace_back("Accept", "application/json");
    const net::HttpResponse response = net::HttpClient(*server, {}, caFile()).send(request);
    if (response.status != 200)
        throw std::runtime_error("TemporaryLtiPlatform: /auth answered " + std::to_string(response.status) + ": " +
                                 response.body.substr(0, 500));
    return nlohmann::json::parse(response.body);
}

nlohmann::json TemporaryLtiPlatform::deepLinkReturn(const std::string& returnUrl, const std::string& jwt) const
{
    std::string error;
    const auto server = net::parseUrl(issuer(), error);
    if (!returnUrl.starts_with(issuer() + "/"))
        throw std::runtime_error("TemporaryLtiPlatform: not this platform's address: " + returnUrl);
    net::HttpRequest request;
    request.method = net::HttpMethod::Post;
    request.target = returnUrl.substr(issuer().size());
    request.body = "JWT=" + net::percentEncode(jwt);
    request.contentType = "application/x-www-form-urlencoded";
    request.headers.emplace_back("Accept", "application/json");
    const net::HttpResponse response = net::HttpClient(*server, {}, caFile()).send(request);
    if (response.status != 200)
        throw std::runtime_error("TemporaryLtiPlatform: the deep-linking answer was refused (" +
                                 std::to_string(response.status) + "): " + response.body.substr(0, 500));
    return nlohmann::json::parse(response.body);
}

} // namespace tlmhub::test
