#pragma once
// Integration-test support: a real tlmhub-server process on an ephemeral loopback port,
// and plain HTTP and WebSocket clients (Boost.Beast, synchronous, with timeouts).
// Only the verb enum: Beast's streams stay in ServerHarness.cpp, so the many test files that
// include this header do not each compile them.
#include <boost/beast/http/verb.hpp>
#include <nlohmann/json.hpp>

#include "TestFiles.h"

#include <chrono>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace tlmhub::test {

// Starts build/bin/tlmhub-server with a data directory; stops it with SIGTERM on destruction.
class ServerProcess {
public:
    // `dataDir` is created if missing and kept (so a test can restart on the same data).
    // `launcher`: a command the server runs under (looked up on PATH), e.g. one that mounts a
    // small file system over the data directory first. A `--listen`, `--workers` or
    // `--password-hash-cost` among `extraArgs` replaces the default one (127.0.0.1:0, 2,
    // minimal), e.g. a port chosen in advance with freeLoopbackPort() for a node that must
    // name its own address.
    ServerProcess(const std::filesystem::path& dataDir, std::vector<std::string> extraArgs = {},
                  std::vector<std::string> launcher = {});
    ~ServerProcess();
    ServerProcess(const ServerProcess&) = delete;
    ServerProcess& operator=(const ServerProcess&) = delete;

    unsigned short port() const { return mPort; }
    int pid() const { return mPid; }   // -1 once it has ended
    // What it printed (stdout and stderr) up to "listening on", and after kill9() or terminate()
    // everything.
    const std::string& output() const { return mOutput; }
    void kill9();          // crash: no cleanup at all
    int terminate();       // SIGTERM, wait; returns the exit status
    // SIGTERM, then waits at most `limit`: the exit status, or nothing if it still runs.
    std::optional<int> terminateWithin(std::chrono::milliseconds limit);
    // Sends `sig` without waiting (SIGSTOP and SIGCONT: a node that stalls and resumes).
    void signal(int sig);

private:
    void collectOutput();   // after the process has ended

    int mPid = -1;
    int mStdout = -1;
    unsigned short mPort = 0;
    std::string mOutput;
    // Reads stdout while the server runs, so that a server that logs a lot never blocks on a
    // full pipe; joined (and its text appended to mOutput) once the process has ended.
    std::thread mDrain;
    std::mutex mDrainMutex;
    std::string mDrained;
};

struct HttpReply {
    int status = 0;
    std::string body;
    std::map<std::string, std::string> headers;
    nlohmann::json json() const { return nlohmann::json::parse(body, nullptr, false); }
};

class HttpClient {
public:
    explicit HttpClient(unsigned short port) : mPort(port) {}
    void setToken(std::string token) { mToken = std::move(token); }
    const std::string& token() const { return mToken; }
    // Sent with every later request (a header may be added more than once).
    void addHeader(std::string name, std::string value) { mHeaders.emplace_back(std::move(name), std::move(value)); }
    HttpReply request(boost::beast::http::verb method, const std::string& target,
                      const std::string& body = {}, const std::string& contentType = "application/json");
    HttpReply get(const std::string& target) { return request(boost::beast::http::verb::get, target); }
    HttpReply post(const std::string& target, const nlohmann::json& body)
    {
        return request(boost::beast::http::verb::post, target, body.dump());
    }
    // Logs in and keeps the token for later requests; returns the token.
    std::string login(const std::string& user, const std::string& password);

private:
    unsigned short mPort;
    std::string mToken;
    std::vector<std::pair<std::string, std::string>> mHeaders;
};

// Where a WebSocket client puts its token: the query string (what browsers do; login tokens
// only) or the upgrade's 'Authorization: Bearer' header (scripts; API tokens too).
enum class WsToken { InQuery, InHeader };

class WsClient {
public:
    // `receiveBufferBytes` > 0 fixes the socket's receive buffer (no autotuning up to
    // megabytes), so a client that stops reading soon leaves the server's frames waiting.
    // Throws boost::system::system_error when the upgrade is refused.
    // `waitForHello` false: a node's connection (it gets no hello).
    WsClient(unsigned short port, const std::string& token, int receiveBufferBytes = 0,
             WsToken where = WsToken::InQuery, bool waitForHello = true);
    ~WsClient();
    WsClient(WsClient&&) noexcept;
    WsClient& operator=(WsClient&&) noexcept;
    void sendText(const std::string& text);
    // Next message, or a null json after `timeoutMs` (the connection is of no further use
    // after a timeout) or when the connection ended. A binary frame comes as the JSON
    // event.frame it stands for; its header is kept in `binaryHeaders`.
    nlohmann::json receive(int timeoutMs = 10000);
    // After receive() returned null: whether the server closed the connection (not a timeout).
    bool closedByServer() const;
    // Sends {"id", "type", ...fields} and returns the reply or error with that id (null when
    // no message comes for `timeoutMs`); events that arrive in between are kept in `events`.
    nlohmann::json call(const std::string& type, nlohmann::json fields = nlohmann::json::object(),
                        int timeoutMs = 10000);
    std::vector<nlohmann::json> events;
    std::vector<nlohmann::json> binaryHeaders;
    nlohmann::json hello;

private:
    struct Connection;   // the Beast stream, its io_context and the last read's error
    std::unique_ptr<Connection> mConnection;
    int mNextId = 1;
};

// A binary event.frame or event.live.frame (protocol/README.md): its JSON header, and the
// whole frame as the JSON event with the same samples. Both throw on a malformed message.
nlohmann::json binaryFrameHeader(const std::string& message);
nlohmann::json binaryFrameAsJson(const std::string& message);

// Whether the server declines the WebSocket upgrade (401) for this token there.
bool websocketUpgradeDeclined(unsigned short port, const std::string& token, WsToken where);

// Sends `bytes` as they are on a new connection and returns everything read until the server
// closes or `timeoutMs` passes without data (for requests a client library would refuse).
std::string rawExchange(unsigned short port, const std::string& bytes, int timeoutMs = 3000);

// A new empty directory tlmhub-NAME-PID in the temporary directory; removed when the test
// program ends with every test passed, kept (and named on stderr) when one failed.
std::filesystem::path freshTempDir(const std::string& name);
// A loopback TCP port nobody listens on right now (bound to port 0, then closed): for a server
// that must know its own port before it starts. Another process may take it in between.
unsigned short freeLoopbackPort();
constexpr const char* kAdminPassword = "admin-secret-pw";

// Test users: `name` logs in with "<name>-password" (the admin with kAdminPassword).
std::string testPassword(const std::string& user);
// Creates each user with role "user" (or "teacher") through the admin (the test fails if one is
// refused).
void createTestUsers(const ServerProcess& server, std::initializer_list<const char*> names);
void createTestTeachers(const ServerProcess& server, std::initializer_list<const char*> names);
// A client of `server` logged in as `user`.
HttpClient loggedInAs(const ServerProcess& server, const std::string& user);
// The id of the first model named `name` in the client's list (its own or an example; the
// test fails if there is none).
std::int64_t modelIdNamed(HttpClient& client, const std::string& name);
// Uploads the .hmf `file` as a model named `name` (the test fails if it is refused); its id.
std::int64_t uploadModel(HttpClient& client, const std::filesystem::path& file, const std::string& name);
// Polls the job until it is neither queued nor running (at most `timeout`); its last JSON.
nlohmann::json waitForJobEnd(HttpClient& client, std::int64_t job,
                             std::chrono::seconds timeout = std::chrono::seconds(120));

} // namespace tlmhub::test
