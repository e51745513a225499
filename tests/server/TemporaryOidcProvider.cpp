#include "TemporaryOidcProvider.h"

#include "net/HttpClient.h"

#include <boost/beast/core/string.hpp>

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace tlmhub::test {

namespace {

// The text between `before` and the next `after` from `from`; "" when not found.
std::string between(const std::string& text, const std::string& before, const std::string& after, std::size_t from = 0)
{
    const std::size_t start = text.find(before, from);
    if (start == std::string::npos) return {};
    const std::size_t end = text.find(after, start + before.size());
    return end == std::string::npos ? std::string{} : text.substr(start + before.size(), end - start - before.size());
}

} // namespace

namespace {

nlohmann::json providerConfig(const std::vector<std::string>& redirectUris, const std::map<std::string, std::string>& accounts)
{
    nlohmann::json accountClaims = nlohmann::json::object();
    for (const auto& [login, claims] : accounts) accountClaims[login] = nlohmann::json::parse(claims);
    return {{"clients",
             {{{"client_id", TemporaryOidcProvider::kClientId},
               {"client_secret", TemporaryOidcProvider::kClientSecret},
               {"redirect_uris", redirectUris},
               {"response_types", {"code"}},
               {"grant_types", {"authorization_code"}}}}},
            {"accounts", accountClaims}};
}

} // namespace

TemporaryOidcProvider::TemporaryOidcProvider(const std::vector<std::string>& redirectUris,
                                             const std::map<std::string, std::string>& accounts)
    : mPeer("oidc-provider", "provider.mjs", "oidc-provider", providerConfig(redirectUris, accounts))
{
}

std::string TemporaryOidcProvider::signInThroughBrowser(const std::string& authorizationUrl, const std::string& login) const
{
    const std::string origin = issuer();
    std::string error;
    const auto server = net::parseUrl(origin, error);
    std::map<std::string, std::string> cookies;
    std::string url = authorizationUrl;
    std::string form;   // the body of a POST, empty for a GET
    for (int step = 0; step < 20; ++step) {
        if (!url.starts_with(origin + "/")) {
            if (url.starts_with("/")) url = origin + url;
            else return url;   // left the provider: the client's callback
        }
        net::HttpRequest request;
        request.method = form.empty() ? net::HttpMethod::Get : net::HttpMethod::Post;
        request.target = url.substr(origin.size());
        if (!form.empty()) {
            request.body = form;
            request.contentType = "application/x-www-form-urlencoded";
        }
        std::string cookieHeader;
        for (const auto& [name, value] : cookies) cookieHeader += (cookieHeader.empty() ? "" : "; ") + name + "=" + value;
        if (!cookieHeader.empty()) request.headers.emplace_back("Cookie", cookieHeader);
        const net::HttpResponse response = net::HttpClient(*server, {}, caFile()).send(request);
        for (const auto& [name, value] : response.headers) {
            if (!boost::beast::iequals(name, "set-cookie")) continue;
            const std::string pair = value.substr(0, value.find(';'));
            cookies[pair.substr(0, pair.find('='))] = pair.substr(pair.find('=') + 1);
        }
        form.clear();
        if (response.status >= 300 && response.status < 400) {
            url = response.header("Location");
            continue;
        }
        // A development page: the login form, then the consent form.
        const std::string action = between(response.body, "action=\"", "\"");
        const std::string prompt = between(response.body, "name=\"prompt\" value=\"", "\"");
        if (response.status != 200 || action.empty() || prompt.empty())
            throw std::runtime_error("TemporaryOidcProvider: unexpected page " + std::to_string(response.status) + ": " +
                                     response.body.substr(0, 500));
        url = action;
        form = prompt == "login" ? "prompt=login&login=" + net::percentEncode(login) + "&password=any" : "prompt=" + prompt;
    }
    throw std::runtime_error("TemporaryOidcProvider: the sign-in did not leave the provider in 20 steps");
}

} // namespace tlmhub::test
