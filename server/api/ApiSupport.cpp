#include "server/api/ApiSupport.h"

#include "server/auth/AccessPolicy.h"
#include "server/http/JsonText.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"
#include "server/protocol/SchemaValidator.h"
#include "server/protocol/UntrustedJson.h"

#include <charconv>
#include <sstream>

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

const char* storeErrorCode(const StoreError& e)
{
    switch (e.code()) {
    case StoreErrc::DiskFull: return "storage_full";
    case StoreErrc::Unavailable:
    case StoreErrc::Busy: return "busy";
    default: return "internal";
    }
}

Response storeErrorResponse(const StoreError& e)
{
    const std::string code = storeErrorCode(e);
    if (code == "storage_full")
        return apiError(http::status::insufficient_storage, code,
                        "the server's disk is full: delete jobs or models to free space");
    if (code == "busy") {
        Response busy = apiError(http::status::service_unavailable, code,
                                 std::string("the database is not available at the moment; try again (") + e.what() + ")");
        busy.set(http::field::retry_after, "1");
        return busy;
    }
    return apiError(http::status::internal_server_error, code, e.what());
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

http::status submitErrorStatus(const std::string& code)
{
    if (code == "limit_exceeded") return http::status::unprocessable_entity;
    if (code == "rate_limited") return http::status::too_many_requests;
    if (code == "not_found") return http::status::not_found;
    if (code == "locked") return http::status::forbidden;
    if (code == "conflict") return http::status::conflict;
    return http::status::bad_request;
}

Response refusal(const std::string& code, const std::string& message)
{
    const http::status status = submitErrorStatus(code);
    Response r = apiError(status, code, message);
    // A per-user count frees up as the user's work moves on: a few seconds is a fair first wait.
    if (status == http::status::too_many_requests) r.set(http::field::retry_after, "5");
    return r;
}

std::vector<std::string> commaSeparated(const std::string& text)
{
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) if (!item.empty()) out.push_back(item);
    return out;
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
    if (!summary) return std::nullopt;
    switch (copyAccess(s.labs.store(), who, id).kind) {
    case CopyAccess::Kind::NotACopy:
        if (!canRead(who, summary->ownerId, summary->isExample)) return std::nullopt;
        return summary;
    case CopyAccess::Kind::None:
        return std::nullopt;
    case CopyAccess::Kind::Read:
    case CopyAccess::Kind::Write:
        return summary;
    }
    return std::nullopt;
}

bool writableModel(Services& s, const User& who, const ModelSummary& model)
{
    switch (copyAccess(s.labs.store(), who, model.id).kind) {
    case CopyAccess::Kind::NotACopy:
        return canWrite(who, model.ownerId, model.isExample);
    case CopyAccess::Kind::Write:
        return true;
    case CopyAccess::Kind::None:
    case CopyAccess::Kind::Read:
        return false;
    }
    return false;
}

} // namespace tlmhub::server
