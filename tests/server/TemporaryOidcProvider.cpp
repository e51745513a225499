#include "TemporaryOidcProvider.h"

#include "ChildProcess.h"
#include "ServerHarness.h"
#include "TestCertificates.h"

#include "net/HttpClient.h"

#include <boost/beast/core/string.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace tlmhub::test {

namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kNode = "/usr/bin/node";
const std::filesystem::path kPeerDir = std::filesystem::path(TLMHUB_SOURCE_DIR) / "tests/peers/oidc-provider";

// The text between `before` and the next `after` from `from`; "" when not found.
std::string between(const std::string& text, const std::string& before, const std::string& after, std::size_t from = 0)
{
    const std::size_t start = text.find(before, from);
    if (start == std::string::npos) return {};
    const std::size_t end = text.find(after, start + before.size());
    return end == std::string::npos ? std::string{} : text.substr(start + before.size(), end - start - before.size());
}

} // namespace

TemporaryOidcProvider::TemporaryOidcProvider(const std::vector<std::string>& redirectUris,
                                             const std::map<std::string, std::string>& accounts)
{
    if (::access(kNode, X_OK) != 0) throw std::runtime_error("TemporaryOidcProvider: Node.js is missing (apt-get install nodejs)");
    if (!std::filesystem::exists(kPeerDir / "node_modules/oidc-provider"))
        throw std::runtime_error("TemporaryOidcProvider: the peer is not installed (npm ci --prefix tests/peers/oidc-provider)");
    char pattern[] = "/tmp/tlmhub-oidc-XXXXXX";
    if (!::mkdtemp(pattern)) throw std::runtime_error("TemporaryOidcProvider: mkdtemp failed");
    mDir = pattern;
    makeTestCertificates(mDir);
    nlohmann::json accountClaims = nlohmann::json::object();
    for (const auto& [login, claims] : accounts) accountClaims[login] = nlohmann::json::parse(claims);

    const auto deadline = Clock::now() + std::chrono::seconds(60);
    for (int attempt = 0;; ++attempt) {
        mPort = freeLoopbackPort();
        const nlohmann::json config = {
            {"port", mPort},
            {"certFile", (mDir / "cert.pem").string()},
            {"keyFile", (mDir / "key.pem").string()},
            {"clients", {{{"client_id", kClientId}, {"client_secret", kClientSecret}, {"redirect_uris", redirectUris},
                          {"response_types", {"code"}}, {"grant_types", {"authorization_code"}}}}},
            {"accounts", accountClaims}};
        std::ofstream(mDir / "config.json") << config.dump();
        mPid = spawn({kNode, (kPeerDir / "provider.mjs").string(), (mDir / "config.json").string()}, mDir / "provider.log",
                     mDir, RunAs{});
        while (Clock::now() < deadline && waitUntil(mPid, Clock::now()) == -1 && logTail().find("ready") == std::string::npos)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (logTail().find("ready") != std::string::npos) return;
        // Ended (the port taken meanwhile) or too slow: again on another port, while there is time.
        stopChild(mPid, std::chrono::seconds(0));
        mPid = -1;
        if (Clock::now() >= deadline || attempt == 3) {
            const std::string log = logTail();
            std::filesystem::remove_all(mDir);
            throw std::runtime_error("TemporaryOidcProvider: the provider did not start: " + log);
        }
    }
}

TemporaryOidcProvider::~TemporaryOidcProvider()
{
    if (mPid > 0) stopChild(mPid, std::chrono::seconds(10));
    std::error_code ec;
    std::filesystem::remove_all(mDir, ec);
}

void TemporaryOidcProvider::restart()
{
    stopChild(mPid, std::chrono::seconds(10));
    std::filesystem::remove(mDir / "provider.log");
    mPid = spawn({kNode, (kPeerDir / "provider.mjs").string(), (mDir / "config.json").string()}, mDir / "provider.log",
                 mDir, RunAs{});
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (Clock::now() < deadline && waitUntil(mPid, Clock::now()) == -1 && logTail().find("ready") == std::string::npos)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (logTail().find("ready") == std::string::npos)
        throw std::runtime_error("TemporaryOidcProvider: the provider did not start again: " + logTail());
}

std::string TemporaryOidcProvider::logTail() const
{
    return tailOf(mDir / "provider.log", 2000);
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
