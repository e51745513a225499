// GET /users, POST /users, PATCH /users/{id}: accounts, administrators only.
#include "server/api/ApiSupport.h"
#include "server/auth/AccessPolicy.h"

namespace tlmhub::server {

namespace {

Response listUsers(Services& s, Call& call)
{
    if (!isAdministrator(call.who()))
        return apiError(http::status::forbidden, "forbidden", "only administrators list users");
    nlohmann::json out = nlohmann::json::array();
    for (const User& u : s.users.list()) out.push_back(publicUser(u));
    return jsonResponse(http::status::ok, out);
}

Response createUser(Services& s, Call& call)
{
    if (!isAdministrator(call.who()))
        return apiError(http::status::forbidden, "forbidden", "only administrators create users");
    protocol::UserCreate body;
    Response error;
    if (!readBody(call, "UserCreate", body, error)) return error;
    std::string why;
    const auto user = s.users.create(body.username, body.password, body.role, why);
    if (!user)
        return why == kUsernameTaken ? apiError(http::status::conflict, "conflict", why)
                                     : apiError(http::status::bad_request, "bad_request", why);
    return jsonResponse(http::status::created, publicUser(*user));
}

// Role and enabled state. A disabled account's logins and API tokens end at once (revoked,
// so enabling it again revives none; open WebSockets closed); a changed role applies to REST
// calls at once and WebSockets reconnect.
Response updateUser(Services& s, Call& call)
{
    if (!isAdministrator(call.who()))
        return apiError(http::status::forbidden, "forbidden", "only administrators change users");
    const auto id = parseId(call.params.path["id"]);
    if (!id) return apiError(http::status::not_found, "not_found", "no such user");
    protocol::UserUpdate body;
    Response error;
    if (!readBody(call, "UserUpdate", body, error)) return error;
    const auto before = s.users.find(*id);
    if (!before) return apiError(http::status::not_found, "not_found", "no such user");
    std::string why;
    const auto user = s.users.update(*id, body.role, body.disabled, why);
    if (!user)
        return why == kLastAdmin ? apiError(http::status::conflict, "conflict", why)
                                 : apiError(http::status::bad_request, "bad_request", why);
    if (user->disabled && !before->disabled) {
        s.tokens.revokeAllFor(user->id);
        s.apiTokens.revokeAllFor(user->id);
        s.liveSessions.sweep();
    } else if (user->role != before->role) {
        s.liveSessions.closeAllOf(user->id, "your role changed: reconnect");
    }
    return jsonResponse(http::status::ok, publicUser(*user));
}

} // namespace

void addUserRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/users", true, listUsers});
    routes.push_back({http::verb::post, "/users", true, createUser, RouteWork::PasswordHash});
    routes.push_back({http::verb::patch, "/users/{id}", true, updateUser});
}

} // namespace tlmhub::server
