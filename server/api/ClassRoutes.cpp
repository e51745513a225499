// /classes: teaching classes, their members, join codes, imported accounts and the
// gradebook (docs/labs.md).
#include "server/api/ApiSupport.h"

#include "server/api/LabSupport.h"
#include "server/auth/AccessPolicy.h"
#include "server/http/HeaderValues.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"
#include "server/live/LiveSessionRegistry.h"
#include "server/store/UnixTime.h"

#include <sstream>

namespace tlmhub::server {

namespace {

constexpr std::size_t kMaxImportedAccounts = 200;

std::string ownerName(Services& s, const ClassInfo& info)
{
    const auto owner = s.users.find(info.ownerId);
    return owner ? owner->username : std::string();
}

Response classReply(Services& s, const ClassView& view, http::status status = http::status::ok)
{
    nlohmann::json out = LabService::classJson(view.info, ownerName(s, view.info), view.role);
    if (view.isStaff()) {
        nlohmann::json members = nlohmann::json::array();
        for (const ClassMember& m : s.labs.store().members(view.info.id))
            members.push_back({{"id", m.userId}, {"username", m.username}, {"role", m.role}, {"joined_at", m.joinedAt}});
        out["members"] = std::move(members);
    }
    return jsonResponse(status, out);
}

Response createClass(Services& s, Call& call)
{
    if (call.who().role != kRoleTeacher && !isAdministrator(call.who()))
        return apiError(http::status::forbidden, "forbidden", "only teachers create classes");
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "ClassCreate", body, error)) return error;
    const auto id = s.labs.createClass(call.who(), body["name"].get<std::string>());
    if (!id) return apiError(http::status::conflict, "conflict", "could not create the class; try again");
    return classReply(s, *classFor(s.labs.store(), call.who(), *id), http::status::created);
}

Response listClasses(Services& s, Call& call)
{
    nlohmann::json classes = nlohmann::json::array();
    if (isAdministrator(call.who())) {
        for (const ClassInfo& info : s.labs.store().listClasses())
            classes.push_back(LabService::classJson(info, ownerName(s, info), kClassTeacher));
    } else {
        for (const Membership& m : s.labs.store().classesOf(call.who().id))
            classes.push_back(LabService::classJson(m.theClass, ownerName(s, m.theClass), m.role));
    }
    return jsonResponse(http::status::ok, {{"classes", classes}});
}

Response getClass(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    return classReply(s, *view);
}

Response updateClass(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher changes it");
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "ClassUpdate", body, error)) return error;
    // Archiving and unarchiving work on an archived class; renaming does not.
    if (body.contains("name")) {
        if (view->info.archived && !(body.contains("archived") && !body["archived"].get<bool>()))
            return labArchived();
        s.labs.store().renameClass(view->info.id, body["name"].get<std::string>());
    }
    if (body.contains("archived")) s.labs.store().setArchived(view->info.id, body["archived"].get<bool>());
    return classReply(s, *classFor(s.labs.store(), call.who(), view->info.id));
}

Response deleteClass(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher deletes it");
    s.labs.store().removeClass(view->info.id);
    return noContent();
}

// Wrong codes count per account and per address, as failed logins do: guessing a code
// (about 59 bits) is hopeless, and the limit makes it slower still.
Response joinClass(Services& s, Call& call)
{
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "ClassJoin", body, error)) return error;
    const std::string userKey = std::to_string(call.who().id);
    const std::string& addressKey = call.clientAddress;
    if (!s.joinLimiter.allowed(userKey) || !s.joinAddressLimiter.allowed(addressKey))
        return apiError(http::status::too_many_requests, "rate_limited", "too many wrong join codes: wait a few minutes");
    std::string code = body["code"].get<std::string>();
    for (char& c : code) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    code.erase(std::remove_if(code.begin(), code.end(), [](char c) { return c == ' ' || c == '-'; }), code.end());
    const auto info = s.labs.store().classByJoinCode(code);
    if (!info) {
        s.joinLimiter.recordFailure(userKey);
        s.joinAddressLimiter.recordFailure(addressKey);
        return apiError(http::status::not_found, "not_found", "no class has this join code");
    }
    if (info->archived) return labArchived();
    if (!s.labs.store().memberRole(info->id, call.who().id))
        s.labs.store().setMember(info->id, call.who().id, kClassStudent);
    return classReply(s, *classFor(s.labs.store(), call.who(), info->id));
}

// One user name per line (the first column of a CSV); a header "username" is skipped.
std::vector<std::string> importedNames(const std::string& body)
{
    std::vector<std::string> names;
    std::istringstream lines(body);
    std::string line;
    while (std::getline(lines, line)) {
        std::string name = line.substr(0, line.find(','));
        const auto notBlank = [](char c) { return c != ' ' && c != '\t' && c != '\r' && c != '"'; };
        name.erase(name.begin(), std::find_if(name.begin(), name.end(), notBlank));
        name.erase(std::find_if(name.rbegin(), name.rend(), notBlank).base(), name.end());
        if (name.empty() || (names.empty() && name == "username")) continue;
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
}

Response importAccounts(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher imports accounts");
    if (view->info.archived) return labArchived();
    const std::vector<std::string> names = importedNames(call.request.body());
    if (names.empty()) return apiError(http::status::bad_request, "bad_request", "the body lists no user names (one per line)");
    if (names.size() > kMaxImportedAccounts)
        return apiError(http::status::bad_request, "bad_request",
                        "at most " + std::to_string(kMaxImportedAccounts) + " accounts per import");
    nlohmann::json accounts = nlohmann::json::array();
    for (const std::string& name : names) {
        nlohmann::json entry = {{"username", name}};
        std::optional<User> user = s.users.findByName(name);
        if (user) {
            entry["created"] = false;
        } else {
            const std::string password = LabService::newJoinCode();
            std::string why;
            user = s.users.create(name, password, kRoleUser, why);
            if (!user) {
                entry["created"] = false;
                entry["error"] = why;
                accounts.push_back(std::move(entry));
                continue;
            }
            entry["created"] = true;
            entry["password"] = password;
        }
        entry["id"] = user->id;
        // An account that teaches or assists in this class keeps that role.
        if (!s.labs.store().memberRole(view->info.id, user->id))
            s.labs.store().setMember(view->info.id, user->id, kClassStudent);
        accounts.push_back(std::move(entry));
    }
    Response res = jsonResponse(http::status::ok, {{"accounts", accounts}});
    res.set(http::field::cache_control, "no-store");   // passwords, shown once
    return res;
}

Response setMember(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher changes members");
    if (view->info.archived) return labArchived();
    const auto userId = parseId(call.params.path["user_id"]);
    const auto user = userId ? s.users.find(*userId) : std::nullopt;
    if (!user) return apiError(http::status::not_found, "not_found", "no such user");
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "MemberUpdate", body, error)) return error;
    const std::string role = body["role"].get<std::string>();
    if (user->id == view->info.ownerId && role != kClassTeacher)
        return apiError(http::status::conflict, "conflict", "the class's creator stays its teacher");
    s.labs.store().setMember(view->info.id, user->id, role);
    return classReply(s, *view);
}

Response removeMember(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher removes members");
    const auto userId = parseId(call.params.path["user_id"]);
    if (!userId || !s.labs.store().memberRole(view->info.id, *userId))
        return apiError(http::status::not_found, "not_found", "no such member");
    if (*userId == view->info.ownerId)
        return apiError(http::status::conflict, "conflict", "the class's creator stays its teacher");
    s.labs.store().removeMember(view->info.id, *userId);
    return noContent();
}

Response gradebook(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher exports grades");
    const auto it = call.params.query.find("format");
    const std::string format = it == call.params.query.end() ? "csv" : it->second;
    if (format == "json") return jsonResponse(http::status::ok, s.labs.gradebookJson(view->info.id));
    if (format != "csv") return apiError(http::status::bad_request, "bad_request", "format must be csv or json");
    Response res = textResponse(http::status::ok, s.labs.gradebookCsv(view->info.id), "text/csv");
    res.set(http::field::content_disposition, attachmentDisposition("gradebook-" + std::to_string(view->info.id) + ".csv"));
    return res;
}

// The live sessions shared with the class on this node (docs/live-sessions.md, "In a lab"):
// what its members may watch with live.subscribe.
Response sharedLiveSessions(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    nlohmann::json sessions = nlohmann::json::array();
    for (const auto& session : s.liveSimulations.sharedWith(view->info.id)) {
        const std::optional<std::int64_t> modelId = session->config().job.modelId;
        const auto model = modelId ? s.models.summary(*modelId) : std::nullopt;
        const auto owner = s.users.find(session->ownerId());
        sessions.push_back({{"session_id", session->id()},
                            {"model_name", model ? model->name : std::string()},
                            {"teacher", {{"id", session->ownerId()}, {"username", owner ? owner->username : std::string()}}}});
    }
    return jsonResponse(http::status::ok, {{"sessions", sessions}});
}

} // namespace

void addClassRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/classes", true, createClass});
    routes.push_back({http::verb::get, "/classes", true, listClasses});
    routes.push_back({http::verb::post, "/classes/join", true, joinClass});
    routes.push_back({http::verb::get, "/classes/{id}", true, getClass});
    routes.push_back({http::verb::patch, "/classes/{id}", true, updateClass});
    routes.push_back({http::verb::delete_, "/classes/{id}", true, deleteClass});
    routes.push_back({http::verb::post, "/classes/{id}/import", true, importAccounts, RouteWork::PasswordHash});
    routes.push_back({http::verb::put, "/classes/{id}/members/{user_id}", true, setMember});
    routes.push_back({http::verb::delete_, "/classes/{id}/members/{user_id}", true, removeMember});
    routes.push_back({http::verb::get, "/classes/{id}/gradebook", true, gradebook});
    routes.push_back({http::verb::get, "/classes/{id}/live", true, sharedLiveSessions});
}

} // namespace tlmhub::server
