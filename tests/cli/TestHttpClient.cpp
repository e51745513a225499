// The HTTP client of the remote CLI and of the server's calls to OpenID providers, against a
// scripted server on loopback: what a real server does only rarely (close a kept connection,
// stall, send too much, answer in chunks), the header fields both ways, and https trusted
// through a given CA file (openssl s_server with a certificate made for the test).
#include "net/HttpClient.h"

#include "server/ChildProcess.h"
#include "server/TestCertificates.h"
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sys/wait.h>

#include <atomic>
#include <functional>
#include <thread>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace tlmhub::net {
namespace {

// Accepts connections on a loopback port and hands each to `serve` (with its index), one
// after the other, on a thread of its own, until destroyed.
class ScriptedServer {
public:
    explicit ScriptedServer(std::function<void(int fd, int index)> serve) : mServe(std::move(serve))
    {
        mListener = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        if (::bind(mListener, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
            ::listen(mListener, 4) != 0 ||
            ::getsockname(mListener, reinterpret_cast<sockaddr*>(&address), &length) != 0)
            throw std::runtime_error("cannot listen on loopback");
        mPort = ntohs(address.sin_port);
        mThread = std::thread([this] {
            for (int index = 0;; ++index) {
                const int fd = ::accept(mListener, nullptr, nullptr);
                if (fd < 0) return;
                ++mAccepted;
                mServe(fd, index);
                ::close(fd);
            }
        });
    }
    ~ScriptedServer()
    {
        ::shutdown(mListener, SHUT_RDWR);   // ends the accept
        ::close(mListener);
        mThread.join();
    }
    Url url() const { return Url{false, "127.0.0.1", std::to_string(mPort), ""}; }
    int accepted() const { return mAccepted; }

private:
    std::function<void(int, int)> mServe;
    int mListener = -1;
    unsigned short mPort = 0;
    std::atomic<int> mAccepted{0};
    std::thread mThread;
};

// Reads one request's head (these requests have no body).
std::string readRequest(int fd)
{
    std::string head;
    char c;
    while (head.find("\r\n\r\n") == std::string::npos && ::read(fd, &c, 1) == 1) head += c;
    return head;
}

HttpRequest get(const std::string& target)
{
    HttpRequest request;
    request.target = target;
    return request;
}

void send(int fd, const std::string& bytes)
{
    ASSERT_EQ(::write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
}

TEST(HttpClient, ReconnectsOnceWhenTheServerClosedAKeptConnection)
{
    ScriptedServer server([](int fd, int index) {
        readRequest(fd);
        send(fd, "HTTP/1.1 200 OK\r\nContent-Length: 3\r\n\r\n" + std::string(index == 0 ? "one" : "two"));
        // and closes, although the response said nothing of it
    });
    HttpClient client(server.url());
    EXPECT_EQ(client.send(get("/a")).body, "one");
    EXPECT_EQ(client.send(get("/b")).body, "two");
    EXPECT_EQ(server.accepted(), 2);
}

TEST(HttpClient, KeepsTheConnectionWhileTheServerDoes)
{
    ScriptedServer server([](int fd, int) {
        for (int i = 0; i < 3; ++i) {
            readRequest(fd);
            send(fd, "HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n2\r\nab\r\n3\r\ncde\r\n0\r\n\r\n");
        }
    });
    HttpClient client(server.url());
    for (int i = 0; i < 3; ++i) EXPECT_EQ(client.send(get("/")).body, "abcde");
    EXPECT_EQ(server.accepted(), 1);
}

TEST(HttpClient, AStalledServerIsGivenUpAfterTheIdleTime)
{
    std::atomic<bool> done{false};
    ScriptedServer server([&](int fd, int) {
        readRequest(fd);
        while (!done) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    });
    HttpClient client(server.url(), {.idle = std::chrono::seconds(1)});
    const auto start = std::chrono::steady_clock::now();
    try {
        client.send(get("/"));
        ADD_FAILURE() << "no ConnectionError";
    } catch (const ConnectionError& e) {
        EXPECT_EQ(std::string(e.what()), "connection to " + server.url().authority() +
                                             " failed while reading the response: no answer within 1 s");
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    done = true;
}

TEST(HttpClient, AResponseOverTheLimitIsRefused)
{
    ScriptedServer server([](int fd, int) {
        readRequest(fd);
        send(fd, "HTTP/1.1 200 OK\r\nContent-Length: 100\r\n\r\n" + std::string(100, 'x'));
    });
    HttpClient client(server.url(), {.maxResponseBytes = 10});
    try {
        client.send(get("/"));
        ADD_FAILURE() << "no ConnectionError";
    } catch (const ConnectionError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "the response from " + server.url().authority() + " is over the limit of 10 bytes");
    }
}

TEST(HttpClient, MoreHeaderFieldsAreSentAndTheResponsesAreRead)
{
    std::string head;
    ScriptedServer server([&](int fd, int) {
        head = readRequest(fd);
        send(fd, "HTTP/1.1 303 See Other\r\nLocation: /next?x=1\r\nSet-Cookie: a=1\r\nset-cookie: b=2\r\n"
                 "Content-Length: 0\r\n\r\n");
    });
    HttpClient client(server.url());
    HttpRequest request = get("/start");
    request.headers = {{"Accept", "application/json"}, {"Authorization", "Basic dGxtaHViOnNlY3JldA=="}};
    request.userAgent = "tlmhub-server";
    const HttpResponse response = client.send(request);
    EXPECT_NE(head.find("\r\nAccept: application/json\r\n"), std::string::npos) << head;
    EXPECT_NE(head.find("\r\nAuthorization: Basic dGxtaHViOnNlY3JldA==\r\n"), std::string::npos) << head;
    EXPECT_NE(head.find("\r\nUser-Agent: tlmhub-server\r\n"), std::string::npos) << head;
    EXPECT_EQ(response.status, 303);
    EXPECT_EQ(response.header("location"), "/next?x=1");
    int cookies = 0;
    for (const auto& [name, value] : response.headers) cookies += name == "Set-Cookie" || name == "set-cookie";
    EXPECT_EQ(cookies, 2);
    EXPECT_EQ(response.header("X-Missing"), "");
}

TEST(HttpClient, AnHttpsServerIsTrustedThroughTheGivenCaFileAndNoOther)
{
    const std::filesystem::path dir = test::freshTempDir("http-client-tls");
    test::makeTestCertificates(dir);
    const unsigned short port = test::freeLoopbackPort();
    const int pid = test::spawn({"/usr/bin/openssl", "s_server", "-accept", "127.0.0.1:" + std::to_string(port), "-cert",
                                 "cert.pem", "-key", "key.pem", "-www", "-quiet"},
                                dir / "s_server.log", dir, {});
    const Url url{true, "127.0.0.1", std::to_string(port), ""};
    std::optional<HttpResponse> answer;
    for (int tries = 0; tries < 100 && !answer; ++tries) {   // until s_server listens
        try {
            answer = HttpClient(url, {.connect = std::chrono::seconds(5)}, dir / "ca.pem").send(get("/"));
        } catch (const ConnectionError&) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    }
    ASSERT_TRUE(answer) << test::tailOf(dir / "s_server.log", 2000);
    EXPECT_EQ(answer->status, 200);
    try {
        HttpClient(url, {}, dir / "other-ca.pem").send(get("/"));
        ADD_FAILURE() << "a certificate of another CA was taken";
    } catch (const ConnectionError& e) {
        EXPECT_NE(std::string(e.what()).find("certificate"), std::string::npos) << e.what();
    }
    try {
        HttpClient(url, {}, dir / "missing.pem");
        ADD_FAILURE() << "a missing CA file was taken";
    } catch (const ConnectionError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.pem"), std::string::npos) << e.what();
    }
    ::kill(pid, SIGTERM);
    test::waitUntil(pid, std::chrono::steady_clock::now() + std::chrono::seconds(10));
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace tlmhub::net
