#pragma once
// A test peer on Node.js (tests/peers/NAME/SCRIPT: an OpenID provider, an LTI platform), started
// by a test: in a temporary directory with a CA and a certificate for 127.0.0.1 made for it
// (TestCertificates.h), on a free loopback port, reading a JSON config file to which `port`,
// `certFile` and `keyFile` are added. Ready once it prints "ready"; a port taken meanwhile
// means another try on another port. A missing Node.js or peer install throws, naming the
// command that installs it (the test fails; nothing is skipped).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace tlmhub::test {

class NodePeer {
public:
    // `installed`: a package in the peer's node_modules whose absence means `npm ci` was not run.
    NodePeer(const std::string& name, const std::string& script, const std::string& installed, nlohmann::json config);
    ~NodePeer();
    NodePeer(const NodePeer&) = delete;
    NodePeer& operator=(const NodePeer&) = delete;

    unsigned short port() const { return mPort; }
    const std::filesystem::path& dir() const { return mDir; }
    std::string logTail() const;
    // Stops the peer and starts it again on the same port, with the same config: whatever it
    // held in memory (keys, codes, sessions) is made anew.
    void restart();

private:
    // Starts the peer; whether it said "ready" before it ended or 60 s passed.
    bool startOnce();

    std::string mName;
    std::filesystem::path mScript, mDir;
    unsigned short mPort = 0;
    int mPid = -1;
};

} // namespace tlmhub::test
