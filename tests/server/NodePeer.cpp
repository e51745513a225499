#include "NodePeer.h"

#include "ChildProcess.h"
#include "ServerHarness.h"
#include "TestCertificates.h"

#include <fstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace tlmhub::test {

namespace {

constexpr const char* kNodeBinary = "/usr/bin/node";

} // namespace

NodePeer::NodePeer(const std::string& name, const std::string& script, const std::string& installed, nlohmann::json config)
    : mName(name)
{
    const auto peerDir = std::filesystem::path(TLMHUB_SOURCE_DIR) / "tests/peers" / name;
    if (::access(kNodeBinary, X_OK) != 0) throw std::runtime_error(name + ": Node.js is missing (apt-get install nodejs)");
    if (!std::filesystem::exists(peerDir / "node_modules" / installed))
        throw std::runtime_error(name + ": the peer is not installed (npm ci --prefix tests/peers/" + name + ")");
    mScript = peerDir / script;
    std::string pattern = "/tmp/tlmhub-" + name + "-XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error(name + ": mkdtemp failed");
    mDir = pattern;
    makeTestCertificates(mDir);
    config["certFile"] = (mDir / "cert.pem").string();
    config["keyFile"] = (mDir / "key.pem").string();
    for (int attempt = 0;; ++attempt) {
        mPort = freeLoopbackPort();
        config["port"] = mPort;
        std::ofstream(mDir / "config.json") << config.dump();
        if (startOnce()) return;
        // Ended (the port taken meanwhile) or too slow: again on another port, a few times.
        stopChild(mPid, std::chrono::seconds(0));
        mPid = -1;
        if (attempt == 3) {
            const std::string log = logTail();
            std::filesystem::remove_all(mDir);
            throw std::runtime_error(name + ": the peer did not start: " + log);
        }
    }
}

NodePeer::~NodePeer()
{
    if (mPid > 0) stopChild(mPid, std::chrono::seconds(10));
    std::error_code ec;
    std::filesystem::remove_all(mDir, ec);
}

bool NodePeer::startOnce()
{
    std::filesystem::remove(mDir / "peer.log");
    mPid = spawn({kNodeBinary, mScript.string(), (mDir / "config.json").string()}, mDir / "peer.log", mDir, RunAs{});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline && waitUntil(mPid, std::chrono::steady_clock::now()) == -1 &&
           logTail().find("ready") == std::string::npos)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return logTail().find("ready") != std::string::npos;
}

void NodePeer::restart()
{
    stopChild(mPid, std::chrono::seconds(10));
    if (!startOnce()) throw std::runtime_error(mName + ": the peer did not start again: " + logTail());
}

std::string NodePeer::logTail() const
{
    return tailOf(mDir / "peer.log", 2000);
}

} // namespace tlmhub::test
