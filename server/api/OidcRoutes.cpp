// GET /auth/providers; the OpenID Connect sign-in: GET /auth/oidc/{name}/start, GET
// /auth/oidc/{name}/callback, POST /auth/oidc/collect (docs/sign-in.md). All public: they
// are how someone without a login gets one.
#include "server/api/ApiSupport.h"
#include "server/http/HeaderValues.h"
#include "server/app/ServerOptions.h"
#include "server/auth/SignInHandOver.h"
#include "server/auth/oidc/OidcSignIn.h"

#include <ctime>
#include <iostream>

namespace tlmhub::server {

namespace {

Response redirect(http::status status, const std::string& location)
{
    Response r = textResponse(status, "", "text/plain");
    r.set(http::field::location, location);
    r.set(http::field::cache_control, "no-store");
    return r;
}

// A refused sign-in's details go to the server's log only (as JSON text: a control character in
// what the provider or the browser sent cannot forge a log line).
void logRefusal(const std::string& provider, const OidcOutcome& refused)
{
    const auto text = [](const std::string& s) {
        return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    };
    std::cerr << "OpenID sign-in with " << text(provider) << " refused (" << refused.code << "): " << text(refused.message)
              << std::endl;
}

// The cookie that ties a provider's answer to the browser that started the sign-in: HttpOnly,
// sent only to these routes, Lax so that the provider's redirect back (a top-level GET) carries it.
constexpr const char* kSignInCookie = "tlmhub_sign_in";

std::string signInCookie(const std::string& value, const std::string& publicUrl, int maxAgeSeconds)
{
    return std::string(kSignInCookie) + "=" + value + "; Path=/api/v1/auth/oidc; Max-Age=" +
           std::to_string(maxAgeSeconds) + "; HttpOnly; SameSite=Lax" + (publicUrl.starts_with("https://") ? "; Secure" : "");
}

std::string queryValue(const Call& call, const char* name)
{
    const auto it = call.params.query.find(name);
    return it == call.params.query.end() ? std::string{} : it->second.substr(0, 4096);
}

Response providers(Services& s, Call&)
{
    protocol::SignInProviders body{.providers = {}, .passwordLogin = s.options.passwordLogin};
    if (s.oidc)
        for (const nlohmann::json& p : s.oidc->providersJson())
            body.providers.push_back({.name = p["name"].get<std::string>(), .displayName = p["display_name"].get<std::string>()});
    return jsonResponse(http::status::ok, body);
}

Response start(Services& s, Call& call)
{
    if (!s.oidc) return apiError(http::status::not_found, "not_found", "no such sign-in provider");
    const OidcOutcome started = s.oidc->start(call.params.path.at("name"), call.clientAddress, std::time(nullptr));
    if (started.code == "not_found") return apiError(http::status::not_found, started.code, started.message);
    // A browser's navigation: a refusal goes back to the login page, which says what to do.
    if (!started.code.empty()) {
        logRefusal(call.params.path.at("name"), started);
        return redirect(http::status::see_other, s.oidc->publicUrl() + "/#/sign-in-failed/" + started.code);
    }
    Response r = redirect(http::status::found, started.location);
    r.set(http::field::set_cookie,
          signInCookie(started.browserKey, s.oidc->publicUrl(), static_cast<int>(OidcSignIn::kSignInSeconds)));
    return r;
}

// Back to the app whatever happened: with a one-time key, or with the reason's code.
Response callback(Services& s, Call& call)
{
    if (!s.oidc) return apiError(http::status::not_found, "not_found", "no such sign-in provider");
    const std::string app = s.oidc->publicUrl() + "/";
    OidcOutcome finished =
        s.oidc->finish(call.params.path.at("name"), queryValue(call, "code"), queryValue(call, "state"), queryValue(call, "iss"),
                       queryValue(call, "error"), requestCookie(call.request, kSignInCookie), std::time(nullptr));
    if (finished.user && finished.user->disabled) finished = OidcOutcome::refused("account_disabled", "the account is disabled");
    Response r = finished.user
        ? redirect(http::status::see_other, app + "#/signed-in/" + s.oidc->handOver(*finished.user, std::time(nullptr)))
        : redirect(http::status::see_other, app + "#/sign-in-failed/" + finished.code);
    if (!finished.user) logRefusal(call.params.path.at("name"), finished);
    r.set(http::field::set_cookie, signInCookie("", s.oidc->publicUrl(), 0));   // used: forgotten
    return r;
}

Response collect(Services& s, Call& call)
{
    protocol::SignInCollect body;
    Response error;
    if (!readBody(call, "SignInCollect", body, error)) return error;
    const auto userId = collectSignIn(s.signIns, body.key, std::time(nullptr));
    const auto user = userId ? s.users.find(*userId) : std::nullopt;
    if (!user || user->disabled)
        return apiError(http::status::unauthorized, "unauthorized", "this sign-in has expired or was collected; sign in again");
    const auto issued = s.tokens.issue(*user);
    return jsonResponse(http::status::ok,
                        protocol::LoginResponse{.token = issued.token, .expiresAt = issued.expiresAt, .user = publicUser(*user)});
}

} // namespace

void addOidcRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/auth/providers", false, providers});
    routes.push_back({http::verb::get, "/auth/oidc/{name}/start", false, start});
    routes.push_back({http::verb::get, "/auth/oidc/{name}/callback", false, callback});
    routes.push_back({http::verb::post, "/auth/oidc/collect", false, collect});
}

} // namespace tlmhub::server
