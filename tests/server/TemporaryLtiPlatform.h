#pragma once
// Test support for LTI 1.3: a learning platform (tests/peers/lti-platform, on npm's jose)
// started by the test (NodePeer.h), knowing the tool at `toolUrl`. Its control routes stage
// launches (with one claim or the signature broken on purpose) and report what the tool sent it.
#include "NodePeer.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace tlmhub::test {

class TemporaryLtiPlatform {
public:
    static constexpr const char* kClientId = "tlmhub-tool";
    static constexpr const char* kDeploymentId = "deployment-1";

    explicit TemporaryLtiPlatform(const std::string& toolUrl);

    std::string issuer() const { return "https://127.0.0.1:" + std::to_string(mPeer.port()); }
    std::filesystem::path caFile() const { return mPeer.dir() / "ca.pem"; }
    std::string logTail() const { return mPeer.logTail(); }
    // The body of POST /admin/lti/platforms that registers this platform.
    nlohmann::json registration() const;

    // A control route: POST with `body` (GET when null); the reply's JSON.
    nlohmann::json control(const std::string& path, const nlohmann::json& body = nullptr) const;
    // What the platform does with the tool's authentication request (its address, from the
    // tool's login redirect): the launch form's fields as JSON {action, id_token, state}, or
    // {action, error, state}.
    nlohmann::json authenticate(const std::string& authenticationUrl) const;

    // What a browser does with the tool's deep-linking answer: posts `jwt` as form field JWT to
    // `returnUrl` (the platform's); the platform's JSON answer ({"placed": [...]}).
    nlohmann::json deepLinkReturn(const std::string& returnUrl, const std::string& jwt) const;

private:
    NodePeer mPeer;
};

} // namespace tlmhub::test
