#include "TemporaryLtiPlatform.h"

#include "ChildProcess.h"
#include "ServerHarness.h"
#include "TestCertificates.h"

#include "net/HttpClient.h"

#include <fstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace tlmhub::test {

namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kLtiNode = "/usr/bin/node";
const std::filesystem::path kLtiPeerDir = std::filesystem::path(TLMHUB_SOURCE_DIR) / "tests/peers/lti-platform";

} // namespace

TemporaryLtiPlatform::TemporaryLtiPlatform(const std::string& toolUrl)
{
    if (::access(kLtiNode, X_OK) != 0) throw std::runtime_error("TemporaryLtiPlatform: Node.js is missing (apt-get install nodejs)");
    if (!std::filesystem::exists(kLtiPeerDir / "node_modules/jose"))
        throw std::runtime_error("TemporaryLtiPlatform: the peer is not installed (npm ci --prefix tests/peers/lti-platform)");
    char pattern[] = "/tmp/tlmhub-lti-XXXXXX";
    if (!::mkdtemp(pattern)) throw std::runtime_error("TemporaryLtiPlatform: mkdtemp failed");
    mDir = pattern;
    makeTestCertificates(mDir);
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    for (int attempt = 0;; ++attempt) {
        mPort = freeLoopbackPort();
        const nlohmann::json config = {{"port", mPort},
                                       {"certFile", (mDir / "cert.pem").string()},
                                       {"keyFile", (mDir / "key.pem").string()},
                                       {"clientId", kClientId},
                                       {"deploymentId", kDeploymentId},
                                       {"tool",
                                        {{"loginUrl", toolUrl + "/api/v1/lti/login"},
                                         {"launchUrl", toolUrl + "/api/v1/lti/launch"},
                                         {"jwksUrl", toolUrl + "/api/v1/lti/jwks"}}}};
        std::ofstream(mDir / "config.json") << config.dump();
        mPid = spawn({kLtiNode, (kLtiPeerDir / "platform.mjs").string(), (mDir / "config.json").string()},
                     mDir / "platform.log", mDir, RunAs{});
        while (Clock::now() < deadline && waitUntil(mPid, Clock::now()) == -1 && logTail().find("ready") == std::string::npos)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (logTail().find("ready") != std::string::npos) return;
        stopChild(mPid, std::chrono::seconds(0));   // ended (its port taken meanwhile) or too slow: again
        mPid = -1;
        if (Clock::now() >= deadline || attempt == 3) {
            const std::string log = logTail();
            std::filesystem::remove_all(mDir);
            throw std::runtime_error("TemporaryLtiPlatform: the platform did not start: " + log);
        }
    }
}

TemporaryLtiPlatform::~TemporaryLtiPlatform()
{
    if (mPid > 0) stopChild(mPid, std::chrono::seconds(10));
    std::error_code ec;
    std::filesystem::remove_all(mDir, ec);
}

std::string TemporaryLtiPlatform::logTail() const
{
    return tailOf(mDir / "platform.log", 2000);
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
