// GET /users, POST /users: accounts, administrators only.
#include "server/api/ApiSupport.h"

namespace tlmhub::server {

namespace {

Response listUsers(Services& s, Call& call)
{
    if (call.who().role != "admin")
        return apiError(http::status::forbidden, "forbidden", "only administrators list users");
    nlohmann::json out = nlohmann::json::array();
    for (const User& u : s.users.list()) out.push_back(userJson(u));
    return jsonResponse(http::status::ok, out);
}

Response createUser(Services& s, Call& call)
{
    if (call.who().role != "admin")
        return apiError(http::status::forbidden, "forbidden", "only administrators create users");
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "UserCreate", body, error)) return error;
    std::string why;
    const auto user = s.users.create(body["username"], body["password"], body.value("role", "user"), why);
    if (!user)
        return why == kUsernameTaken ? apiError(http::status::conflict, "conflict", why)
                                     : apiError(http::status::bad_request, "bad_request", why);
    return jsonResponse(http::status::created, userJson(*user));
}

} // namespace

void addUserRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/users", true, listUsers});
    routes.push_back({http::verb::post, "/users", true, createUser});
}

} // namespace tlmhub::server
