#include "server/api/ApiSupport.h"

#include "server/auth/AccessPolicy.h"
#include "server/http/JsonText.h"
#include "server/protocol/SchemaValidator.h"
#include "server/protocol/UntrustedJson.h"

#include <charconv>

namespace tlmhub::server {

Response jsonResponse(http::status status, const nlohmann::json& body)
{
    Response res{status, 11};
    res.set(http::field::content_type, "application/json");
    res.body() = toJsonText(body);
    return res;
}

Response textResponse(http::status status, std::string body, const std::string& contentType)
{
    Response res{status, 11};
    res.set(http::field::content_type, contentType);
    res.body() = std::move(body);
    return res;
}

Response noContent()
{
    return Response{http::status::no_content, 11};
}

Response apiError(http::status status, const std::string& code, const std::string& message)
{
    return jsonResponse(status, protocol::ErrorBody{.error = {.code = code, .message = message}});
}

bool readJsonBody(const Call& call, const std::string& definition, nlohmann::json& body,
                  Response& error)
{
    UntrustedJson parsed = parseUntrustedJson(call.request.body());
    if (!parsed.ok()) {
        error = apiError(http::status::bad_request, "bad_json", "request body: " + parsed.error);
        return false;
    }
    body = std::move(parsed.value);
    std::string why;
    if (!definition.empty() && !SchemaValidator::protocol().validate(definition, body, why)) {
        error = apiError(http::status::bad_request, "schema_violation", why);
        return false;
    }
    return true;
}

std::optional<std::int64_t> parseId(const std::string& text)
{
    std::int64_t id = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), id);
    if (ec != std::errc() || ptr != text.data() + text.size() || id <= 0) return std::nullopt;
    return id;
}

bool isXmlRequest(const Request& request)
{
    const std::string type(request[http::field::content_type]);
    return type.find("xml") != std::string::npos;
}

bool wantsXml(const Call& call)
{
    const auto format = call.params.query.find("format");
    if (format != call.params.query.end()) return format->second == "hmf" || format->second == "xml";
    const std::string accept(call.request[http::field::accept]);
    return accept.find("application/xml") != std::string::npos;
}

protocol::User publicUser(const User& user)
{
    return {.id = user.id, .username = user.username, .role = user.role, .disabled = user.disabled};
}

nlohmann::json modelSummaryJson(const ModelSummary& m)
{
    return protocol::ModelSummary{.id = m.id,
                                  .name = m.name,
                                  .owner = {.id = m.ownerId, .username = m.ownerName},
                                  .isExample = m.isExample,
                                  .createdAt = m.createdAt,
                                  .updatedAt = m.updatedAt};
}

std::optional<ModelSummary> readableModel(Services& s, const User& who, std::int64_t id)
{
    auto summary = s.models.summary(id);
    if (!summary || !canRead(who, summary->ownerId, summary->ownerRole, summary->isExample))
        return std::nullopt;
    return summary;
}

} // namespace tlmhub::server
