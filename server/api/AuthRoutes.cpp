// POST /auth/login, POST /auth/logout, GET /auth/me, POST /auth/password
#include "server/api/ApiSupport.h"

namespace tlmhub::server {

namespace {

Response login(Services& s, Call& call)
{
    protocol::LoginRequest body;
    Response error;
    if (!readBody(call, "LoginRequest", body, error)) return error;
    const std::string& username = body.username;
    // Failures are counted per user name and per address, so guessing one account's
    // password and spraying one password over many accounts are both slowed down.
    const std::string userKey = "user:" + username;
    const std::string addressKey = "addr:" + call.clientAddress;
    if (!s.loginLimiter.allowed(userKey) || !s.addressLimiter.allowed(addressKey))
        return apiError(http::status::too_many_requests, "rate_limited",
                        "too many failed logins; try again later");
    const auto user = s.users.authenticate(username, body.password);
    if (!user) {
        s.loginLimiter.recordFailure(userKey);
        s.addressLimiter.recordFailure(addressKey);
        return apiError(http::status::unauthorized, "unauthorized", "wrong user name or password");
    }
    s.loginLimiter.recordSuccess(userKey);
    if (user->disabled)
        return apiError(http::status::forbidden, "account_disabled",
                        "this account is disabled; ask an administrator");
    const auto issued = s.tokens.issue(*user);
    return jsonResponse(http::status::ok, protocol::LoginResponse{
                                              .token = issued.token, .expiresAt = issued.expiresAt, .user = publicUser(*user)});
}

Response logout(Services& s, Call& call)
{
    s.tokens.revoke(call.token);
    s.liveSessions.sweep();   // WebSockets opened with this login end now
    return noContent();
}

Response me(Services&, Call& call)
{
    return jsonResponse(http::status::ok, publicUser(call.who()));
}

Response changePassword(Services& s, Call& call)
{
    protocol::PasswordChange body;
    Response error;
    if (!readBody(call, "PasswordChange", body, error)) return error;
    std::string why;
    if (!s.users.changePassword(call.who().id, body.oldPassword, body.newPassword, why))
        return apiError(http::status::bad_request, "bad_request", why);
    // Every session opened with the old password ends, this one too: log in again.
    s.tokens.revokeAllFor(call.who().id);
    s.liveSessions.sweep();
    return noContent();
}

Response downloadLink(Services& s, Call& call)
{
    protocol::DownloadLinkRequest body;
    Response error;
    if (!readBody(call, "DownloadLinkRequest", body, error)) return error;
    const std::string& target = body.target;
    if (target.find(std::string(DownloadLinks::kParameter) + "=") != std::string::npos)
        return apiError(http::status::bad_request, "bad_request", "the target already holds a download link");
    const auto link = s.downloadLinks.sign(target, call.who().id);
    return jsonResponse(http::status::ok, protocol::DownloadLink{.url = link.url, .expiresAt = link.expiresAt});
}

} // namespace

void addAuthRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/auth/login", false, login, RouteWork::PasswordHash});
    routes.push_back({http::verb::post, "/auth/logout", true, logout});
    routes.push_back({http::verb::get, "/auth/me", true, me});
    routes.push_back({http::verb::post, "/auth/password", true, changePassword, RouteWork::PasswordHash});
    routes.push_back({http::verb::post, "/auth/download-link", true, downloadLink});
}

} // namespace tlmhub::server
