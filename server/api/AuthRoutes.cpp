// POST /auth/login, POST /auth/logout, GET /auth/me, POST /auth/password
#include "server/api/ApiSupport.h"
#include "server/app/ServerOptions.h"
#include "server/auth/DirectorySignIn.h"
#include "server/jobs/JobQueue.h"
#include "server/store/ResultStore.h"

#include <algorithm>
#include <iostream>

namespace tlmhub::server {

namespace {

Response login(Services& s, Call& call)
{
    protocol::LoginRequest body;
    Response error;
    if (!readBody(call, "LoginRequest", body, error)) return error;
    const std::string& username = body.username;
    // Failures are counted per user name at an address, and per address. Guessing one account's
    // password from one place is slowed down without locking its owner out from another; a
    // NAT's or a proxy's many users share the address limit, which only failures reach, and a
    // correct password for an account not itself limited still logs in past it.
    const std::string userKey = username + '\n' + call.clientAddress;
    const std::string& addressKey = call.clientAddress;
    const auto limited = [](LoginRateLimiter& limiter, const std::string& key) {
        Response r = apiError(http::status::too_many_requests, "rate_limited", "too many failed logins; try again later");
        r.set(http::field::retry_after, std::to_string(limiter.retryAfter(key).count()));
        return r;
    };
    if (!s.loginLimiter.allowed(userKey)) return limited(s.loginLimiter, userKey);
    const bool addressLimited = !s.addressLimiter.allowed(addressKey);
    const bool passwordAllowed = s.options.passwordLogin || std::ranges::find(s.options.localLoginUsers, username) !=
                                                                s.options.localLoginUsers.end();
    std::optional<User> user = passwordAllowed ? s.users.authenticate(username, body.password) : std::nullopt;
    // Not a local account's password: the directory's, when there is one (the same limits).
    if (!user && s.directory) {
        const DirectorySignInResult signedIn = s.directory->signIn(username, body.password);
        using Outcome = DirectorySignInResult::Outcome;
        if (signedIn.outcome == Outcome::Unavailable) {
            // The name as a JSON string: a control character in it cannot forge a log line.
            std::cerr << "LDAP sign-in of " << nlohmann::json(username).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)
                      << ": " << signedIn.message << std::endl;
            // Why stays in the log: it names the directory's address and the service account.
            Response r = apiError(http::status::service_unavailable, "directory_unavailable",
                                  "the directory cannot be asked now; try again later (the server's log says why)");
            r.set(http::field::retry_after, "30");
            return r;
        }
        if (signedIn.outcome == Outcome::NoAccount) {
            s.loginLimiter.recordSuccess(userKey);
            return apiError(http::status::forbidden, "no_account", signedIn.message);
        }
        user = signedIn.user;
    }
    if (!user && !passwordAllowed && !s.directory)
        return apiError(http::status::forbidden, "password_login_off",
                        "this server's own passwords are turned off: sign in through your organisation");
    if (!user) {
        s.loginLimiter.recordFailure(userKey);
        s.addressLimiter.recordFailure(addressKey);
        if (addressLimited) return limited(s.addressLimiter, addressKey);
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

Response me(Services& s, Call& call)
{
    const protocol::User user = publicUser(call.who());
    return jsonResponse(http::status::ok,
                        protocol::CurrentUser{
                            .id = user.id, .username = user.username, .role = user.role, .disabled = user.disabled,
                            .storedBytes = static_cast<std::int64_t>(s.queue.results().storedBytes(user.id)),
                            .quotaBytes = static_cast<std::int64_t>(s.options.limits.maxStoredBytesPerUser)});
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
    if (const std::string problem = DownloadLinks::targetProblem(target); !problem.empty())
        return apiError(http::status::bad_request, "bad_request", problem);
    // A link ends with the login it was made in; a script's API token sends its header instead.
    if (ApiTokens::isApiToken(call.token))
        return apiError(http::status::forbidden, "forbidden",
                        "download links are for browser logins; with an API token, send the Authorization header");
    const auto link = s.downloadLinks.sign(target, call.who().id, TokenService::sessionKey(call.token));
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
