#pragma once
// The tlmhub REST API (/api/v1) as the remote commands use it: JSON in and out, the bearer
// token on every call, and the server's {"error":{code,message}} turned into an ApiError.
#include "net/HttpClient.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace tlmhub::cli::remote {

// The HTTP client and the server's address, shared with the server (net/).
using net::ConnectionError;
using net::HttpClient;
using net::HttpLimits;
using net::HttpMethod;
using net::HttpRequest;
using net::HttpResponse;
using net::parseUrl;
using net::percentEncode;
using net::Url;

// An answer of 400 or above; what() is "CODE: message" as the server gave them.
class ApiError : public std::runtime_error {
public:
    ApiError(int status, const std::string& code, const std::string& message);
    int status() const { return mStatus; }
    const std::string& code() const { return mCode; }

private:
    int mStatus;
    std::string mCode;
};

// A reply's field when it is there with the expected type (a number, or text), else
// `fallback`: replies have null for what is not known yet (a queued job's steps).
template <class T>
T field(const nlohmann::json& reply, const std::string& key, T fallback)
{
    const auto it = reply.find(key);
    if (it == reply.end()) return fallback;
    if constexpr (std::is_arithmetic_v<T>) return it->is_number() ? it->template get<T>() : fallback;
    else return it->is_string() ? it->template get<T>() : fallback;
}

class ApiClient {
public:
    // `token`: an API token or a login session's token; empty for login itself.
    ApiClient(const Url& server, std::string token);

    // `path` below /api/v1, e.g. "/jobs/3".
    nlohmann::json get(const std::string& path);
    nlohmann::json post(const std::string& path, const nlohmann::json& body);
    nlohmann::json postXml(const std::string& path, const std::string& xml);
    nlohmann::json del(const std::string& path);
    // The body as it came (CSV), byte for byte.
    std::string getText(const std::string& path);

    const Url& server() const { return mHttp.server(); }
    void setToken(std::string token) { mToken = std::move(token); }

private:
    HttpResponse call(HttpMethod method, const std::string& path, const std::string& body,
                      const std::string& contentType);
    nlohmann::json parse(const HttpResponse& response, const std::string& path) const;

    HttpClient mHttp;
    std::string mToken;
};

} // namespace tlmhub::cli::remote
