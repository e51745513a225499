#include "ServerHarness.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <mutex>
#include <poll.h>
#include <set>
#include <sstream>
#include <stdexcept>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace tlmhub::test {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

// The directories freshTempDir made in this process: removed when the tests end (a full run
// left about 1.5 GB of servers' data in /tmp), or, when a test failed, kept for a look.
std::mutex gTempDirsMutex;
std::set<std::filesystem::path> gTempDirs;

class RemoveTempDirsAtEnd : public ::testing::Environment {
public:
    void TearDown() override
    {
        const bool passed = ::testing::UnitTest::GetInstance()->Passed();
        std::lock_guard lock(gTempDirsMutex);
        for (const std::filesystem::path& dir : gTempDirs) {
            std::error_code ignored;
            if (passed) std::filesystem::remove_all(dir, ignored);
            else std::cerr << "a test failed: its data is kept in " << dir.string() << "\n";
        }
        gTempDirs.clear();
    }
};
[[maybe_unused]] ::testing::Environment* const gRemoveTempDirs =
    ::testing::AddGlobalTestEnvironment(new RemoveTempDirsAtEnd);

} // namespace

std::filesystem::path freshTempDir(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() /
                     ("tlmhub-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::lock_guard lock(gTempDirsMutex);
    gTempDirs.insert(dir);
    return dir;
}

unsigned short freeLoopbackPort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw std::runtime_error("freeLoopbackPort: socket failed");
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
        ::close(fd);
        throw std::runtime_error("freeLoopbackPort: cannot bind a loopback port");
    }
    ::close(fd);
    return ntohs(address.sin_port);
}

ServerProcess::ServerProcess(const std::filesystem::path& dataDir, std::vector<std::string> extraArgs,
                             std::vector<std::string> launcher)
{
    std::filesystem::create_directories(dataDir);
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    const auto given = [&](const char* flag) {
        return std::find(extraArgs.begin(), extraArgs.end(), flag) != extraArgs.end();
    };
    std::vector<std::string> args = {TLMHUB_SERVER_BIN, "--data-dir", dataDir.string(), "--examples-dir",
                                     std::string(TLMHUB_SOURCE_DIR) + "/examples", "--web-root",
                                     (dataDir / "no-web").string()};
    if (!given("--listen")) args.insert(args.end(), {"--listen", "127.0.0.1:0"});
    if (!given("--workers")) args.insert(args.end(), {"--workers", "2"});
    // Test users log in hundreds of times a run: 0.1 s of argon2 each was a fifth of the
    // server tests' CPU time. A test about hashing load passes "interactive".
    if (!given("--password-hash-cost")) args.insert(args.end(), {"--password-hash-cost", "minimal"});
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    args.insert(args.begin(), launcher.begin(), launcher.end());
    mPid = ::fork();
    if (mPid == 0) {
        // Its log, both streams: what it reports (stdout) and what went wrong (stderr).
        ::dup2(fds[1], STDOUT_FILENO);
        ::dup2(fds[1], STDERR_FILENO);
        ::close(fds[0]);
        ::close(fds[1]);
        ::setenv("TLMHUB_ADMIN_PASSWORD", kAdminPassword, 1);
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execvp(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(fds[1]);
    mStdout = fds[0];
    // Read stdout until the "listening on" line (at most 30 s).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    const std::string marker = "listening on http://127.0.0.1:";
    while (std::chrono::steady_clock::now() < deadline) {
        pollfd p{mStdout, POLLIN, 0};
        if (::poll(&p, 1, 200) <= 0) continue;
        char buf[512];
        const ssize_t n = ::read(mStdout, buf, sizeof buf);
        if (n <= 0) break;
        mOutput.append(buf, static_cast<std::size_t>(n));
        const auto at = mOutput.find(marker);
        if (at != std::string::npos && mOutput.find('\n', at) != std::string::npos) {
            mPort = static_cast<unsigned short>(std::stoi(mOutput.substr(at + marker.size())));
            mDrain = std::thread([this] {
                char chunk[4096];
                ssize_t got;
                while ((got = ::read(mStdout, chunk, sizeof chunk)) > 0) {
                    std::lock_guard lock(mDrainMutex);
                    mDrained.append(chunk, static_cast<std::size_t>(got));
                }
            });
            return;
        }
    }
    throw std::runtime_error("tlmhub-server did not start; output: " + mOutput);
}

ServerProcess::~ServerProcess()
{
    if (mPid > 0) terminate();
    collectOutput();
    if (mStdout >= 0) ::close(mStdout);
}

void ServerProcess::collectOutput()
{
    // The pipe's write end closed with the process: the drain thread reads to its end.
    if (mDrain.joinable()) mDrain.join();
    char buf[4096];
    ssize_t n;
    if (mStdout >= 0)
        while ((n = ::read(mStdout, buf, sizeof buf)) > 0) mDrained.append(buf, static_cast<std::size_t>(n));
    mOutput += mDrained;
    mDrained.clear();
}

void ServerProcess::signal(int sig)
{
    if (mPid > 0) ::kill(mPid, sig);
}

void ServerProcess::kill9()
{
    if (mPid <= 0) return;   // ended already (kill(-1, ...) would signal every process)
    ::kill(mPid, SIGKILL);
    int status = 0;
    ::waitpid(mPid, &status, 0);
    mPid = -1;
    collectOutput();
}

int ServerProcess::terminate()
{
    if (mPid <= 0) return 0;
    ::kill(mPid, SIGTERM);
    ::kill(mPid, SIGCONT);   // a stopped process (signal(SIGSTOP)) handles SIGTERM only once resumed
    int status = 0;
    ::waitpid(mPid, &status, 0);
    mPid = -1;
    collectOutput();
    return status;
}

std::optional<int> ServerProcess::terminateWithin(std::chrono::milliseconds limit)
{
    if (mPid <= 0) return 0;
    ::kill(mPid, SIGTERM);
    ::kill(mPid, SIGCONT);
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
        int status = 0;
        if (::waitpid(mPid, &status, WNOHANG) == mPid) {
            mPid = -1;
            collectOutput();
            return status;
        }
        if (std::chrono::steady_clock::now() > deadline) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

HttpReply HttpClient::request(http::verb method, const std::string& target, const std::string& body,
                              const std::string& contentType)
{
    net::io_context ioc;
    beast::tcp_stream stream(ioc);
    stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), mPort));
    http::request<http::string_body> req{method, target, 11};
    req.set(http::field::host, "127.0.0.1");
    if (!mToken.empty()) req.set(http::field::authorization, "Bearer " + mToken);
    for (const auto& [name, value] : mHeaders) req.insert(name, value);
    if (!body.empty()) {
        req.set(http::field::content_type, contentType);
        req.body() = body;
    }
    req.prepare_payload();
    // The server may answer (413) and close before the whole body is sent: read anyway.
    beast::error_code writeError;
    http::write(stream, req, writeError);
    beast::flat_buffer buffer;
    http::response_parser<http::string_body> parser;
    parser.body_limit(1u << 30);
    http::read(stream, buffer, parser);
    auto res = parser.release();
    HttpReply reply;
    reply.status = static_cast<int>(res.result_int());
    reply.body = res.body();
    for (const auto& field : res) reply.headers[std::string(field.name_string())] = std::string(field.value());
    beast::error_code ignored;
    stream.socket().shutdown(tcp::socket::shutdown_both, ignored);
    return reply;
}

std::string HttpClient::login(const std::string& user, const std::string& password)
{
    const HttpReply r = post("/api/v1/auth/login", {{"username", user}, {"password", password}});
    if (r.status != 200) throw std::runtime_error("login failed: " + r.body);
    mToken = r.json()["token"].get<std::string>();
    return mToken;
}

namespace {

// Connects `ws` and sends the upgrade with the token where `where` says.
void upgrade(beast::websocket::stream<tcp::socket>& ws, unsigned short port, const std::string& token, WsToken where,
             beast::error_code& ec)
{
    ws.next_layer().connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
    if (where == WsToken::InHeader) {
        ws.set_option(beast::websocket::stream_base::decorator([token](beast::websocket::request_type& request) {
            request.set(beast::http::field::authorization, "Bearer " + token);
        }));
    }
    ws.handshake("127.0.0.1", where == WsToken::InQuery ? "/api/v1/ws?token=" + token : "/api/v1/ws", ec);
}

} // namespace

struct WsClient::Connection {
    net::io_context ioc;
    beast::websocket::stream<tcp::socket> ws{ioc};
    beast::error_code lastError;
};

WsClient::WsClient(unsigned short port, const std::string& token, int receiveBufferBytes, WsToken where,
                   bool waitForHello)
    : mConnection(std::make_unique<Connection>())
{
    auto& ws = mConnection->ws;
    ws.next_layer().open(tcp::v4());
    if (receiveBufferBytes > 0)   // before connecting: the window is agreed at the handshake
        ws.next_layer().set_option(net::socket_base::receive_buffer_size(receiveBufferBytes));
    beast::error_code ec;
    upgrade(ws, port, token, where, ec);
    if (ec) throw boost::system::system_error(ec);
    if (waitForHello) hello = receive();
}

WsClient::~WsClient() = default;
WsClient::WsClient(WsClient&&) noexcept = default;
WsClient& WsClient::operator=(WsClient&&) noexcept = default;

bool websocketUpgradeDeclined(unsigned short port, const std::string& token, WsToken where)
{
    net::io_context ioc;
    beast::websocket::stream<tcp::socket> ws(ioc);
    beast::error_code ec;
    upgrade(ws, port, token, where, ec);
    return ec == beast::websocket::error::upgrade_declined;
}

void WsClient::sendText(const std::string& text)
{
    mConnection->ws.text(true);
    mConnection->ws.write(net::buffer(text));
}

nlohmann::json WsClient::receive(int timeoutMs)
{
    // Asynchronous with a deadline: a blocking read would wait for ever on a server that
    // neither answers nor closes (a receive timeout on the socket does not stop Asio).
    // References, not a structured binding: clang 14 cannot capture bindings in a lambda.
    net::io_context& ioc = mConnection->ioc;
    beast::websocket::stream<tcp::socket>& ws = mConnection->ws;
    beast::error_code& lastError = mConnection->lastError;
    beast::flat_buffer buffer;
    bool done = false;
    ws.async_read(buffer, [&](beast::error_code ec, std::size_t) {
        lastError = ec;
        done = true;
    });
    ioc.restart();
    ioc.run_for(std::chrono::milliseconds(timeoutMs));
    if (!done) {
        beast::error_code ignored;
        ws.next_layer().cancel(ignored);
        ioc.restart();
        ioc.run();
        lastError = net::error::timed_out;
    }
    if (lastError) return nlohmann::json();
    const std::string message = beast::buffers_to_string(buffer.data());
    if (!ws.got_text()) {
        binaryHeaders.push_back(binaryFrameHeader(message));
        return binaryFrameAsJson(message);
    }
    return nlohmann::json::parse(message, nullptr, false);
}

nlohmann::json binaryFrameHeader(const std::string& message)
{
    std::uint32_t headerBytes = 0;
    if (message.size() < 4) throw std::runtime_error("binary frame shorter than its header length");
    std::memcpy(&headerBytes, message.data(), 4);   // little-endian, as this machine
    if (4 + std::size_t{headerBytes} > message.size()) throw std::runtime_error("binary frame header past the end");
    return nlohmann::json::parse(message.substr(4, headerBytes));
}

nlohmann::json binaryFrameAsJson(const std::string& message)
{
    const nlohmann::json header = binaryFrameHeader(message);
    std::uint32_t headerBytes = 0;
    std::memcpy(&headerBytes, message.data(), 4);
    std::size_t at = (4 + std::size_t{headerBytes} + 7) / 8 * 8;
    for (std::size_t i = 4 + headerBytes; i < at; ++i)
        if (message[i] != '\0') throw std::runtime_error("binary frame padding is not zero");
    auto take = [&](std::size_t n) {
        if (at + n * 8 > message.size()) throw std::runtime_error("binary frame samples past the end");
        std::vector<double> values(n);
        std::memcpy(values.data(), message.data() + at, n * 8);
        at += n * 8;
        return values;
    };
    nlohmann::json event = {{"type", header.at("type")}, {"seq", header.at("seq")}, {"dropped", header.at("dropped")}};
    // A job's frame names its job; a live session's its session and when it was taken.
    for (const char* key : {"job_id", "session_id", "model_time", "wall_time"})
        if (header.contains(key)) event[key] = header[key];
    event["time"] = take(header.at("time_samples").get<std::size_t>());
    event["variables"] = nlohmann::json::object();
    for (const auto& v : header.at("variables"))
        event["variables"][v.at("name").get<std::string>()] = take(v.at("samples").get<std::size_t>());
    if (at != message.size()) throw std::runtime_error("binary frame has bytes after its samples");
    return event;
}

bool WsClient::closedByServer() const
{
    const beast::error_code& error = mConnection->lastError;
    return error == beast::websocket::error::closed || error == net::error::eof ||
           error == net::error::connection_reset;
}

std::string rawExchange(unsigned short port, const std::string& bytes, int timeoutMs)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        ::close(fd);
        throw std::runtime_error("cannot connect to the server");
    }
    for (std::size_t sent = 0; sent < bytes.size();) {
        const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) break;
        sent += static_cast<std::size_t>(n);
    }
    std::string received;
    char buf[65536];
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, timeoutMs) <= 0) break;
        const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
        if (n <= 0) break;
        received.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return received;
}

nlohmann::json WsClient::call(const std::string& type, nlohmann::json fields, int timeoutMs)
{
    const int id = mNextId++;
    fields["id"] = id;
    fields["type"] = type;
    sendText(fields.dump());
    for (int i = 0; i < 100000; ++i) {
        nlohmann::json m = receive(timeoutMs);
        if (m.is_null()) return m;
        if (m.contains("id") && m["id"] == id) return m;
        events.push_back(std::move(m));
    }
    return nlohmann::json();
}

std::string testPassword(const std::string& user)
{
    return user == "admin" ? kAdminPassword : user + "-password";
}

namespace {
void createTestAccounts(const ServerProcess& server, std::initializer_list<const char*> names, const char* role)
{
    HttpClient admin = loggedInAs(server, "admin");
    for (const char* name : names) {
        const auto r = admin.post("/api/v1/users", {{"username", name}, {"password", testPassword(name)}, {"role", role}});
        EXPECT_EQ(r.status, 201) << name << ": " << r.body;
    }
}
} // namespace

void createTestUsers(const ServerProcess& server, std::initializer_list<const char*> names)
{
    createTestAccounts(server, names, "user");
}

void createTestTeachers(const ServerProcess& server, std::initializer_list<const char*> names)
{
    createTestAccounts(server, names, "teacher");
}

HttpClient loggedInAs(const ServerProcess& server, const std::string& user)
{
    HttpClient c(server.port());
    c.login(user, testPassword(user));
    return c;
}

std::int64_t modelIdNamed(HttpClient& client, const std::string& name)
{
    for (const auto& m : client.get("/api/v1/models").json())
        if (m["name"] == name) return m["id"].get<std::int64_t>();
    ADD_FAILURE() << "no model named " << name;
    return 0;
}

std::int64_t uploadModel(HttpClient& client, const std::filesystem::path& file, const std::string& name)
{
    const auto r = client.request(boost::beast::http::verb::post, "/api/v1/models?name=" + name, readFile(file),
                                  "application/xml");
    EXPECT_EQ(r.status, 201) << r.body;
    return r.status == 201 ? r.json()["id"].get<std::int64_t>() : 0;
}

nlohmann::json waitForJobEnd(HttpClient& client, std::int64_t job, std::chrono::seconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    nlohmann::json info;
    do {
        info = client.get("/api/v1/jobs/" + std::to_string(job)).json();
        const std::string state = info.value("state", "");
        if (state != "queued" && state != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    } while (std::chrono::steady_clock::now() < deadline);
    return info;
}

} // namespace tlmhub::test
