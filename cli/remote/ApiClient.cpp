#include "cli/remote/ApiClient.h"

namespace tlmhub::cli::remote {

ApiError::ApiError(int status, const std::string& code, const std::string& message)
    : std::runtime_error(code + ": " + message), mStatus(status), mCode(code)
{
}

ApiClient::ApiClient(const Url& server, std::string token) : mHttp(server), mToken(std::move(token)) {}

HttpResponse ApiClient::call(HttpMethod method, const std::string& path, const std::string& body,
                             const std::string& contentType)
{
    HttpResponse response =
        mHttp.send({.method = method, .target = server().prefix + "/api/v1" + path, .body = body,
                    .contentType = contentType, .bearerToken = mToken});
    if (response.status < 400) return response;
    const nlohmann::json reply = nlohmann::json::parse(response.body, nullptr, false);
    if (reply.is_object() && reply.contains("error") && reply["error"].is_object()) {
        const nlohmann::json& error = reply["error"];
        throw ApiError(response.status, field(error, "code", "http_" + std::to_string(response.status)),
                       field(error, "message", std::string()));
    }
    // Not the API's answer (a proxy's error page, a server without this route).
    std::string excerpt = response.body.substr(0, 200);
    for (char& c : excerpt)
        if (c == '\n' || c == '\r') c = ' ';
    throw ApiError(response.status, "http_" + std::to_string(response.status),
                   "HTTP " + std::to_string(response.status) + " from " + server().text() +
                       "/api/v1" + path + (excerpt.empty() ? "" : ": " + excerpt));
}

nlohmann::json ApiClient::parse(const HttpResponse& response, const std::string& path) const
{
    if (response.body.empty()) return nlohmann::json::object();   // 204
    nlohmann::json reply = nlohmann::json::parse(response.body, nullptr, false);
    if (reply.is_discarded())
        throw ApiError(response.status, "bad_reply", "the answer to " + path + " is not JSON");
    return reply;
}

nlohmann::json ApiClient::get(const std::string& path)
{
    return parse(call(HttpMethod::Get, path, "", ""), path);
}

nlohmann::json ApiClient::post(const std::string& path, const nlohmann::json& body)
{
    return parse(call(HttpMethod::Post, path, body.dump(), "application/json"), path);
}

nlohmann::json ApiClient::del(const std::string& path)
{
    return parse(call(HttpMethod::Delete, path, "", ""), path);
}

nlohmann::json ApiClient::postXml(const std::string& path, const std::string& xml)
{
    return parse(call(HttpMethod::Post, path, xml, "application/xml"), path);
}

std::string ApiClient::getText(const std::string& path)
{
    return call(HttpMethod::Get, path, "", "").body;
}

} // namespace tlmhub::cli::remote
