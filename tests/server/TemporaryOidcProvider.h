#pragma once
// Test support for OpenID Connect sign-in: a real provider (npm's oidc-provider, pinned in
// tests/peers/oidc-provider) started by the test (NodePeer.h), and a browser's walk through its
// development login and consent pages.
#include "NodePeer.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tlmhub::test {

class TemporaryOidcProvider {
public:
    static constexpr const char* kClientId = "tlmhub";
    static constexpr const char* kClientSecret = "tlmhub-test-client-secret";

    // `redirectUris`: the client's registered callbacks; `accounts`: login name -> claims JSON
    // (an object's text, e.g. {"name":"Jane Doe","groups":["teachers"]}).
    TemporaryOidcProvider(const std::vector<std::string>& redirectUris, const std::map<std::string, std::string>& accounts);

    std::string issuer() const { return "https://127.0.0.1:" + std::to_string(mPeer.port()); }
    std::filesystem::path caFile() const { return mPeer.dir() / "ca.pem"; }
    std::filesystem::path otherCaFile() const { return mPeer.dir() / "other-ca.pem"; }
    std::string logTail() const { return mPeer.logTail(); }
    // Stops the provider and starts it again on the same port: it signs with a new key (a
    // rotation), and whatever it held in memory (codes, sessions) is gone.
    void restart() { mPeer.restart(); }

    // What a browser does from the provider's authorization address: signs in as `login`
    // (any password), consents, and follows the redirects until one leaves the provider;
    // returns that address (the client's callback with code and state, or error).
    std::string signInThroughBrowser(const std::string& authorizationUrl, const std::string& login) const;

private:
    NodePeer mPeer;
};

} // namespace tlmhub::test
