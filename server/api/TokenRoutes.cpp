// POST /tokens, GET /tokens, DELETE /tokens/{id}: the caller's personal API tokens.
#include "server/api/ApiSupport.h"

namespace tlmhub::server {

namespace {

protocol::TokenInfo tokenInfo(const ApiTokenInfo& t)
{
    return {.id = t.id, .name = t.name, .createdAt = t.createdAt, .expiresAt = t.expiresAt, .lastUsedAt = t.lastUsedAt};
}

Response create(Services& s, Call& call)
{
    protocol::TokenCreate body;
    Response error;
    if (!readBody(call, "TokenCreate", body, error)) return error;
    auto creation = s.apiTokens.create(call.who(), body.name, body.expiresInDays);
    if (!creation.created)
        return refusal(creation.code, creation.message);
    const ApiTokenInfo& t = creation.created->info;
    return jsonResponse(http::status::created,
                        protocol::TokenCreated{.id = t.id, .name = t.name, .token = creation.created->token,
                                               .createdAt = t.createdAt, .expiresAt = t.expiresAt,
                                               .lastUsedAt = t.lastUsedAt});
}

Response list(Services& s, Call& call)
{
    protocol::TokenList out;
    for (const ApiTokenInfo& t : s.apiTokens.list(call.who())) out.tokens.push_back(tokenInfo(t));
    return jsonResponse(http::status::ok, out);
}

Response revoke(Services& s, Call& call)
{
    const auto id = parseId(call.params.path["id"]);
    if (!id || !s.apiTokens.revoke(call.who(), *id))
        return apiError(http::status::not_found, "not_found", "you have no API token with that id");
    s.liveSessions.sweep();   // WebSockets opened with this token end now
    return noContent();
}

} // namespace

void addTokenRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/tokens", true, create});
    routes.push_back({http::verb::get, "/tokens", true, list});
    routes.push_back({http::verb::delete_, "/tokens/{id}", true, revoke});
}

} // namespace tlmhub::server
