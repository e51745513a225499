#include "server/auth/oidc/ProviderHttp.h"

#include "net/HttpClient.h"

namespace tlmhub::server {

ProviderHttp::ProviderHttp(std::filesystem::path caFile) : mCaFile(std::move(caFile)) {}

std::optional<ProviderReply> ProviderHttp::getJson(const std::string& url, std::string& error) const
{
    return send(url, false, {}, {}, {}, true, error);
}

std::optional<JsonWebKeySet> ProviderHttp::getKeySet(const std::string& url, std::string& error) const
{
    const auto reply = getJson(url, error);
    if (!reply) return std::nullopt;
    if (reply->status != 200) {
        error = "the key set " + url.substr(0, 200) + " answered " + std::to_string(reply->status);
        return std::nullopt;
    }
    return JsonWebKeySet::parse(reply->body, error);
}

std::optional<ProviderReply> ProviderHttp::postForm(const std::string& url, const std::string& form,
                                                    const std::vector<std::pair<std::string, std::string>>& headers,
                                                    std::string& error) const
{
    return send(url, true, "application/x-www-form-urlencoded", form, headers, true, error);
}

std::optional<ProviderReply> ProviderHttp::post(const std::string& url, const std::string& contentType,
                                                const std::string& body,
                                                const std::vector<std::pair<std::string, std::string>>& headers,
                                                std::string& error) const
{
    return send(url, true, contentType, body, headers, false, error);
}

std::optional<ProviderReply> ProviderHttp::send(const std::string& url, bool post, const std::string& contentType,
                                                const std::string& content,
                                                const std::vector<std::pair<std::string, std::string>>& headers,
                                                bool needsJson, std::string& error) const
{
    constexpr std::string_view scheme = "https://";
    const std::size_t pathStart = url.starts_with(scheme) ? url.find_first_of("/?", scheme.size()) : std::string::npos;
    const std::string origin = url.substr(0, pathStart);
    std::optional<net::Url> server = url.starts_with(scheme) ? net::parseUrl(origin, error) : std::nullopt;
    if (!server) {
        error = "not an https address: " + url.substr(0, 200) + (error.empty() ? "" : " (" + error + ")");
        return std::nullopt;
    }
    net::HttpRequest request;
    request.method = post ? net::HttpMethod::Post : net::HttpMethod::Get;
    request.target = pathStart == std::string::npos ? "/" : url.substr(pathStart);
    if (request.target.front() == '?') request.target.insert(0, "/");
    request.userAgent = "tlmhub-server";
    request.headers = headers;
    request.headers.emplace_back("Accept", "application/json");
    if (post) {
        request.contentType = contentType;
        request.body = content;
    }
    try {
        net::HttpClient client(*server,
                               {.connect = std::chrono::seconds(5), .idle = std::chrono::seconds(5),
                                .maxResponseBytes = kMaxReplyBytes},
                               mCaFile);
        net::HttpResponse response = client.send(request);
        nlohmann::json body = nlohmann::json::parse(response.body, nullptr, false);
        if (body.is_discarded() && needsJson) {
            error = url.substr(0, 200) + " answered " + std::to_string(response.status) + " without JSON";
            return std::nullopt;
        }
        if (body.is_discarded()) body = nullptr;
        return ProviderReply{response.status, std::move(body)};
    } catch (const net::ConnectionError& e) {
        error = e.what();
        return std::nullopt;
    }
}

} // namespace tlmhub::server
