// tlmhub as an LTI 1.3 tool (docs/sign-in.md): the platforms' public routes GET /lti/jwks,
// GET|POST /lti/login, POST /lti/launch and the launch page GET /lti/app; a teacher's deep
// linking, GET|POST /lti/deep-links/{key}; and the administrators' registry of platforms,
// /admin/lti/platforms[/{id}].
#include "server/api/ApiSupport.h"
#include "server/auth/AccessPolicy.h"
#include "server/auth/lti/LtiTool.h"
#include "server/http/HeaderValues.h"
#include "server/http/SecurityHeaders.h"
#include "server/labs/LabService.h"
#include "server/store/LtiStore.h"
#include "server/store/ModelName.h"

#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace tlmhub::server {

namespace {

// The cookie that ties a platform's launch to the browser its login came through. The launch is
// a cross-site form post, often inside the platform's frame: only SameSite=None (which needs
// Secure) is sent along, and inside a frame only a Partitioned cookie (CHIPS: kept for this
// server under the platform's site) when the browser blocks third-party cookies, as Chromium
// does by default.
constexpr const char* kLtiCookie = "tlmhub_lti";

std::string ltiCookie(const std::string& value, int maxAgeSeconds)
{
    return std::string(kLtiCookie) + "=" + value + "; Path=/api/v1/lti; Max-Age=" + std::to_string(maxAgeSeconds) +
           "; HttpOnly; Secure; SameSite=None; Partitioned";
}

// Pages shown inside a platform's frame (the launch page, a refused launch) may be framed by the
// registered platforms.
void allowPlatformFrames(Services& s, Response& r)
{
    r.set("Content-Security-Policy", std::string(kContentSecurityPolicyWithoutFrameAncestors) +
                                         "; frame-ancestors " + s.lti->frameAncestors());
}

// A form post's fields (application/x-www-form-urlencoded), or the query's for a GET.
std::map<std::string, std::string> ltiFields(const Call& call)
{
    if (call.request.method() == http::verb::get) return call.params.query;
    return parseRequestTarget("/?" + call.request.body()).query;
}

std::string ltiField(const std::map<std::string, std::string>& fields, const char* name)
{
    const auto it = fields.find(name);
    return it == fields.end() ? std::string{} : it->second.substr(0, 64 * 1024);
}

// What a person in the platform's frame reads when a launch is refused: the code (the details
// go to the server's log only) and what to do. Codes are [a-z_] and the text is ours.
Response ltiRefusalPage(Services& s, const LtiOutcome& refused)
{
    std::cerr << "LTI launch refused (" << refused.code << "): "
              << nlohmann::json(refused.message).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)
              << std::endl;
    const bool busy = refused.code == "busy";
    const char* advice = refused.code == "course_not_ready"
        ? "Your teacher has not opened tlmhub from this course yet. Try again once they have."
        : refused.code == "wrong_browser"
        ? "Your browser did not send tlmhub's cookie inside the course page. Open the activity in a new window and try again."
        : busy ? "Too many launches at once. Wait a minute and try again."
               : "Go back to the course and open the activity again. If it keeps failing, tell the course's teacher this code.";
    Response r = textResponse(busy ? http::status::too_many_requests : http::status::bad_request,
                              "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>tlmhub: launch refused"
                              "</title></head><body><h1>The launch was refused</h1><p>" +
                                  std::string(advice) + "</p><p>Code: <code>" + refused.code + "</code></p></body></html>",
                              "text/html; charset=utf-8");
    if (busy) r.set(http::field::retry_after, "60");
    r.set(http::field::cache_control, "no-store");
    allowPlatformFrames(s, r);
    return r;
}

Response ltiOff()
{
    return apiError(http::status::not_found, "not_found", "LTI is off: start the server with --lti-key-file and --public-url");
}

// The browser app's page for launches: the app, with a policy that lets the registered
// platforms frame it (every other page may be framed by this server only).
Response launchPage(Services& s, Call&)
{
    if (!s.lti) return ltiOff();
    std::ifstream in(std::filesystem::path(s.options.webRoot) / "index.html", std::ios::binary);
    if (!in) return apiError(http::status::not_found, "not_found", "the web app is not built");
    std::ostringstream page;
    page << in.rdbuf();
    Response r = textResponse(http::status::ok, page.str(), "text/html; charset=utf-8");
    allowPlatformFrames(s, r);
    r.set(http::field::cache_control, "no-cache");
    return r;
}

Response keySet(Services& s, Call&)
{
    if (!s.lti) return ltiOff();
    Response r = jsonResponse(http::status::ok, s.lti->keys().keySet());
    r.set(http::field::cache_control, "max-age=300");
    return r;
}

Response login(Services& s, Call& call)
{
    if (!s.lti) return ltiOff();
    const auto fields = ltiFields(call);
    const LtiLoginRequest request{ltiField(fields, "iss"),         ltiField(fields, "login_hint"),
                                  ltiField(fields, "target_link_uri"), ltiField(fields, "lti_message_hint"),
                                  ltiField(fields, "client_id"),   ltiField(fields, "lti_deployment_id")};
    const LtiOutcome started = s.lti->login(request, call.clientAddress, std::time(nullptr));
    if (!started.code.empty()) return ltiRefusalPage(s, started);
    Response r = textResponse(http::status::found, "", "text/plain");
    r.set(http::field::location, started.location);
    r.set(http::field::cache_control, "no-store");
    r.set(http::field::set_cookie, ltiCookie(started.browserKey, static_cast<int>(LtiTool::kLaunchSeconds)));
    return r;
}

Response launch(Services& s, Call& call)
{
    if (!s.lti) return ltiOff();
    const auto fields = ltiFields(call);
    LtiOutcome launched = s.lti->launch(ltiField(fields, "id_token"), ltiField(fields, "state"), ltiField(fields, "error"),
                                        requestCookie(call.request, kLtiCookie), std::time(nullptr));
    if (!launched.user) return ltiRefusalPage(s, launched);
    Response r = textResponse(http::status::see_other, "", "text/plain");
    r.set(http::field::location, launched.location);
    r.set(http::field::cache_control, "no-store");
    r.set(http::field::set_cookie, ltiCookie("", 0));   // used: forgotten
    return r;
}

// The teacher's deep-linking launch waiting under the path's key: 404 for anyone else.
std::optional<LtiDeepLinkRequest> callersDeepLink(Services& s, const Call& call)
{
    return s.lti ? s.lti->deepLinkOf(call.params.path.at("key"), call.who().id, std::time(nullptr)) : std::nullopt;
}

Response deepLinkNotFound()
{
    return apiError(http::status::not_found, "not_found", "this placement has expired or was used; add the activity again");
}

Response getDeepLink(Services& s, Call& call)
{
    const auto request = callersDeepLink(s, call);
    const auto platform = request ? s.ltiPlatforms.platform(request->platformId) : std::nullopt;
    if (!platform) return deepLinkNotFound();
    return jsonResponse(http::status::ok, protocol::LtiDeepLink{request->classId, platform->name,
                                                                request->createdAt + LtiTool::kLaunchSeconds});
}

Response placeDeepLink(Services& s, Call& call)
{
    const auto request = callersDeepLink(s, call);
    if (!request) return deepLinkNotFound();
    protocol::LtiDeepLinkPlace body;
    Response error;
    if (!readBody(call, "LtiDeepLinkPlace", body, error)) return error;
    const auto assignment = s.labs.store().assignment(body.assignmentId);
    if (!assignment || assignment->classId != request->classId)
        return apiError(http::status::not_found, "not_found", "no such assignment in the course's class");
    const auto jwt = s.lti->placeAssignment(*request, *assignment, std::time(nullptr));
    if (!jwt) return deepLinkNotFound();
    return jsonResponse(http::status::ok, protocol::LtiDeepLinkAnswer{request->returnUrl, *jwt});
}

protocol::LtiPlatform platformJson(const LtiPlatform& p)
{
    return {p.id, p.name, p.issuer, p.clientId, p.authUrl, p.tokenUrl, p.jwksUrl, p.deploymentIds, p.createdAt};
}

bool readPlatform(const Call& call, LtiPlatform& platform, Response& error)
{
    protocol::LtiPlatformSettings body;
    if (!readBody(call, "LtiPlatformSettings", body, error)) return false;
    platform.name = body.name;
    platform.issuer = body.issuer;
    platform.clientId = body.clientId;
    platform.authUrl = body.authUrl;
    platform.tokenUrl = body.tokenUrl;
    platform.jwksUrl = body.jwksUrl;
    platform.deploymentIds = body.deploymentIds;
    std::set<std::string> deployments(platform.deploymentIds.begin(), platform.deploymentIds.end());
    if (deployments.size() != platform.deploymentIds.size()) {
        error = apiError(http::status::bad_request, "bad_request", "deployment_ids: a deployment is listed twice");
        return false;
    }
    for (const std::string* text : {&platform.name, &platform.clientId})
        if (const std::string problem = nameCharacterProblem(*text); !problem.empty()) {
            error = apiError(http::status::bad_request, "bad_request", problem);
            return false;
        }
    return true;
}

Response forbiddenUnlessAdmin(const Call& call, bool& allowed)
{
    allowed = isAdministrator(call.who());
    return allowed ? Response{} : apiError(http::status::forbidden, "forbidden", "only administrators manage platforms");
}

Response listPlatforms(Services& s, Call& call)
{
    bool allowed = false;
    if (Response refused = forbiddenUnlessAdmin(call, allowed); !allowed) return refused;
    protocol::LtiPlatformList out;
    for (const LtiPlatform& p : s.ltiPlatforms.listPlatforms()) out.platforms.push_back(platformJson(p));
    if (s.lti) out.tool = {true, s.lti->loginUrl(), s.lti->launchUrl(), s.lti->launchUrl(), s.lti->keySetUrl()};
    return jsonResponse(http::status::ok, out);
}

Response createPlatform(Services& s, Call& call)
{
    bool allowed = false;
    if (Response refused = forbiddenUnlessAdmin(call, allowed); !allowed) return refused;
    LtiPlatform platform;
    Response error;
    if (!readPlatform(call, platform, error)) return error;
    const auto id = s.ltiPlatforms.addPlatform(platform);
    if (!id) return apiError(http::status::conflict, "conflict", "a platform with that issuer and client id is registered");
    return jsonResponse(http::status::created, platformJson(*s.ltiPlatforms.platform(*id)));
}

Response getPlatform(Services& s, Call& call)
{
    bool allowed = false;
    if (Response refused = forbiddenUnlessAdmin(call, allowed); !allowed) return refused;
    const auto id = parseId(call.params.path.at("id"));
    const auto platform = id ? s.ltiPlatforms.platform(*id) : std::nullopt;
    if (!platform) return apiError(http::status::not_found, "not_found", "no such platform");
    return jsonResponse(http::status::ok, platformJson(*platform));
}

Response updatePlatform(Services& s, Call& call)
{
    bool allowed = false;
    if (Response refused = forbiddenUnlessAdmin(call, allowed); !allowed) return refused;
    const auto id = parseId(call.params.path.at("id"));
    if (!id || !s.ltiPlatforms.platform(*id)) return apiError(http::status::not_found, "not_found", "no such platform");
    LtiPlatform platform;
    Response error;
    if (!readPlatform(call, platform, error)) return error;
    platform.id = *id;
    if (!s.ltiPlatforms.updatePlatform(platform))
        return apiError(http::status::conflict, "conflict", "another platform has that issuer and client id");
    return jsonResponse(http::status::ok, platformJson(*s.ltiPlatforms.platform(*id)));
}

Response removePlatform(Services& s, Call& call)
{
    bool allowed = false;
    if (Response refused = forbiddenUnlessAdmin(call, allowed); !allowed) return refused;
    const auto id = parseId(call.params.path.at("id"));
    if (!id || !s.ltiPlatforms.removePlatform(*id)) return apiError(http::status::not_found, "not_found", "no such platform");
    return noContent();
}

} // namespace

void addLtiRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/lti/jwks", false, keySet, RouteWork::Instant});
    routes.push_back({http::verb::get, "/lti/login", false, login});
    routes.push_back({http::verb::post, "/lti/login", false, login});
    routes.push_back({http::verb::post, "/lti/launch", false, launch});
    routes.push_back({http::verb::get, "/lti/app", false, launchPage});
    routes.push_back({http::verb::get, "/lti/deep-links/{key}", true, getDeepLink});
    routes.push_back({http::verb::post, "/lti/deep-links/{key}", true, placeDeepLink});
    routes.push_back({http::verb::get, "/admin/lti/platforms", true, listPlatforms});
    routes.push_back({http::verb::post, "/admin/lti/platforms", true, createPlatform});
    routes.push_back({http::verb::get, "/admin/lti/platforms/{id}", true, getPlatform});
    routes.push_back({http::verb::put, "/admin/lti/platforms/{id}", true, updatePlatform});
    routes.push_back({http::verb::delete_, "/admin/lti/platforms/{id}", true, removePlatform});
}

} // namespace tlmhub::server
