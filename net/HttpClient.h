#pragma once
// A synchronous HTTP/1.1 client for one server (Boost.Beast; https through OpenSSL, the
// certificate verified against the system's CAs or a given CA file). It keeps the connection
// open between requests while the server allows it, and reconnects once when a kept
// connection turns out to be closed.
#include "net/Url.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tlmhub::net {

enum class HttpMethod { Get, Post, Delete };

struct HttpRequest {
    HttpMethod method = HttpMethod::Get;
    std::string target;          // path and query, e.g. "/api/v1/jobs/3"
    std::string body;
    std::string contentType;     // with a body
    std::string bearerToken;     // empty: no Authorization header
    std::vector<std::pair<std::string, std::string>> headers;   // more fields (Accept, Authorization: Basic ...)
    std::string userAgent = "tlmhub-cli";
};

struct HttpResponse {
    int status = 0;
    std::string body;
    std::vector<std::pair<std::string, std::string>> headers;   // as received, in order

    // The first field named `name` (any case); "" when there is none.
    std::string header(std::string_view name) const;
};

// The server could not be reached, the TLS handshake failed, or the exchange broke off; the
// message names the server (host:port) and the reason.
class ConnectionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct HttpLimits {
    std::chrono::seconds connect{15};   // TCP connect and TLS handshake
    std::chrono::seconds idle{60};      // longest wait for the next bytes of a request or response
    // Job results are at most 64 MiB of samples on the server; as %.17g text that is a few
    // times more. Past this the response is refused rather than filling memory.
    std::uint64_t maxResponseBytes = std::uint64_t{1} << 30;
};

class HttpClient {
public:
    // `caFile`: the CAs an https server's certificate must chain to; empty: the system's.
    explicit HttpClient(Url server, HttpLimits limits = {}, const std::filesystem::path& caFile = {});
    ~HttpClient();
    HttpClient(const HttpClient&) = delete;
    HttpClient& operator=(const HttpClient&) = delete;

    // Any HTTP status is a response; throws ConnectionError when there is none.
    HttpResponse send(const HttpRequest& request);
    const Url& server() const;

private:
    class Connection;
    std::unique_ptr<Connection> mConnection;
};

} // namespace tlmhub::net
