// /classes/{id}/assignments and /assignments: assignments, their checks, a student's copy,
// pretests and hand-ins, and the teacher's dashboard and overlay plot (docs/labs.md).
#include "server/api/ApiSupport.h"

#include "server/api/LabSupport.h"
#include "server/auth/lti/LtiTool.h"
#include "server/labs/ParameterLock.h"
#include "server/store/UnixTime.h"

#include <charconv>

namespace tlmhub::server {

namespace {

Response onlyTeacher(const std::string& what)
{
    return apiError(http::status::forbidden, "forbidden", "only the class's teacher " + what);
}

Response onlyStudent(const std::string& what)
{
    return apiError(http::status::forbidden, "forbidden", "only students " + what);
}

// The text of a model the teacher may read (a template or a solution), or an error response.
std::optional<std::string> teacherModel(Services& s, const Call& call, const nlohmann::json& id, const char* field,
                                        Response& error)
{
    const auto model = readableModel(s, call.who(), id.get<std::int64_t>());
    const auto hmf = model ? s.models.hmf(model->id) : std::nullopt;
    if (!hmf) {
        error = apiError(http::status::not_found, "not_found", std::string(field) + ": no such model");
        return std::nullopt;
    }
    return hmf;
}

// Fills `info` from the create or update body; false with the error response.
bool readAssignmentFields(const nlohmann::json& body, AssignmentInfo& info, Response& error)
{
    if (body.contains("title")) info.title = body["title"].get<std::string>();
    if (body.contains("instructions")) info.instructions = body["instructions"].get<std::string>();
    if (body.contains("edit_mode")) info.editMode = body["edit_mode"].get<std::string>();
    if (body.contains("opens_at")) info.opensAt = body["opens_at"].get<std::int64_t>();
    if (body.contains("due_at")) info.dueAt = body["due_at"].get<std::int64_t>();
    if (body.contains("parameters")) {
        std::string why;
        const auto lock = ParameterLock::parse(body["parameters"], why);
        if (!lock) {
            error = apiError(http::status::bad_request, "bad_request", "body." + why);
            return false;
        }
        info.parameters = lock->toJson().dump();
    }
    if (info.dueAt != 0 && info.dueAt < info.opensAt) {
        error = apiError(http::status::bad_request, "bad_request", "body.due_at: is before opens_at");
        return false;
    }
    return true;
}

nlohmann::json studentAssignmentJson(Services& s, const AssignmentInfo& a, const User& student)
{
    nlohmann::json out = LabService::assignmentJson(a);
    out["status"] = s.labs.studentStatus(a, student.id);
    const auto copy = s.labs.store().copy(a.id, student.id);
    out["copy"] = copy ? s.labs.copyJson(a, *copy) : nlohmann::json(nullptr);
    return out;
}

// The assignment as its teacher sees it: with what they are warned of (AssignmentWarnings.h).
nlohmann::json teacherAssignmentJson(Services& s, const AssignmentInfo& a)
{
    nlohmann::json out = LabService::assignmentJson(a);
    out["warnings"] = warningsJson(s.labs.warnings(a));
    return out;
}

Response createAssignment(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    if (!view->isTeacher()) return onlyTeacher("creates assignments");
    if (view->info.archived) return labArchived();
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "AssignmentCreate", body, error)) return error;
    AssignmentInfo info;
    info.classId = view->info.id;
    info.editMode = "free";
    info.parameters = "[]";
    info.opensAt = unixNow();
    if (!readAssignmentFields(body, info, error)) return error;
    const auto templateHmf = teacherModel(s, call, body["template_model_id"], "template_model_id", error);
    if (!templateHmf) return error;
    std::optional<std::string> solutionHmf;
    if (body.contains("solution_model_id")) {
        solutionHmf = teacherModel(s, call, body["solution_model_id"], "solution_model_id", error);
        if (!solutionHmf) return error;
    }
    const auto id = s.labs.store().createAssignment(info, *templateHmf, "");
    if (!id) return labNotFound("class");
    if (solutionHmf) {
        if (const auto failed = s.labs.setSolution(*id, *solutionHmf)) {
            s.labs.store().removeAssignment(*id);
            return labErrorResponse(*failed);
        }
    }
    return jsonResponse(http::status::created, teacherAssignmentJson(s, *s.labs.store().assignment(*id)));
}

Response listAssignments(Services& s, Call& call)
{
    const auto view = visibleClass(s, call);
    if (!view) return labNotFound("class");
    const std::int64_t now = unixNow();
    nlohmann::json list = nlohmann::json::array();
    for (const AssignmentInfo& a : s.labs.store().assignmentsOf(view->info.id)) {
        if (!view->isStudent()) list.push_back(LabService::assignmentJson(a));
        else if (a.opensAt <= now) list.push_back(studentAssignmentJson(s, a, call.who()));
    }
    return jsonResponse(http::status::ok, {{"assignments", list}});
}

Response getAssignment(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (view->classView.isStudent())
        return jsonResponse(http::status::ok, studentAssignmentJson(s, view->assignment, call.who()));
    if (view->classView.isTeacher()) return jsonResponse(http::status::ok, teacherAssignmentJson(s, view->assignment));
    return jsonResponse(http::status::ok, LabService::assignmentJson(view->assignment));
}

Response updateAssignment(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (!view->classView.isTeacher()) return onlyTeacher("changes assignments");
    if (view->classView.info.archived) return labArchived();
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "AssignmentUpdate", body, error)) return error;
    AssignmentInfo info = view->assignment;
    if (!readAssignmentFields(body, info, error)) return error;
    std::optional<std::string> templateHmf, solutionHmf;
    if (body.contains("template_model_id") &&
        !(templateHmf = teacherModel(s, call, body["template_model_id"], "template_model_id", error)))
        return error;
    if (body.contains("solution_model_id") &&
        !(solutionHmf = teacherModel(s, call, body["solution_model_id"], "solution_model_id", error)))
        return error;
    if (solutionHmf)
        if (const auto failed = s.labs.setSolution(info.id, *solutionHmf)) return labErrorResponse(*failed);
    s.labs.store().updateAssignment(info);
    if (templateHmf) s.labs.publishTemplate(view->assignment, *templateHmf);
    return jsonResponse(http::status::ok, teacherAssignmentJson(s, *s.labs.store().assignment(info.id)));
}

Response deleteAssignment(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (!view->classView.isTeacher()) return onlyTeacher("deletes assignments");
    s.labs.store().removeAssignment(view->assignment.id);
    return noContent();
}

Response putChecks(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (!view->classView.isTeacher()) return onlyTeacher("sets checks");
    if (view->classView.info.archived) return labArchived();
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "ChecksUpdate", body, error)) return error;
    std::vector<AssignmentCheck> checks;
    for (const nlohmann::json& c : body["checks"])
        checks.push_back({0, c["name"].get<std::string>(), c.value("pretest", false), c["points"].get<double>(),
                          c["definition"].dump()});
    if (const auto failed = s.labs.setChecks(view->assignment, checks)) return labErrorResponse(*failed);
    return jsonResponse(http::status::ok, {{"checks", checksJson(s.labs.store().checks(view->assignment.id), true)}});
}

Response getChecks(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    return jsonResponse(http::status::ok,
                        {{"checks", checksJson(s.labs.store().checks(view->assignment.id), view->classView.isStaff())}});
}

// The student's own copy: refused to staff (they read students' copies from the dashboard).
std::optional<AssignmentView> studentAssignment(Services& s, Call& call, const char* what, Response& error)
{
    auto view = visibleAssignment(s, call);
    if (!view) {
        error = labNotFound("assignment");
        return std::nullopt;
    }
    if (!view->classView.isStudent()) {
        error = onlyStudent(what);
        return std::nullopt;
    }
    if (view->classView.info.archived) {
        error = labArchived();
        return std::nullopt;
    }
    return view;
}

Response openAssignment(Services& s, Call& call)
{
    Response error;
    const auto view = studentAssignment(s, call, "open assignments", error);
    if (!view) return error;
    bool created = false;
    LabError failure;
    const auto copy = s.labs.openCopy(view->assignment, call.who(), created, failure);
    if (!copy) return labErrorResponse(failure);
    return jsonResponse(created ? http::status::created : http::status::ok,
                        {{"copy", s.labs.copyJson(view->assignment, *copy)}});
}

Response resetCopy(Services& s, Call& call)
{
    Response error;
    const auto view = studentAssignment(s, call, "reset their copies", error);
    if (!view) return error;
    LabError failure;
    const auto copy = s.labs.resetCopy(view->assignment, call.who(), failure);
    if (!copy) return labErrorResponse(failure);
    return jsonResponse(http::status::ok, {{"copy", s.labs.copyJson(view->assignment, *copy)}});
}

// The pretests' outcome of run `jobId` once it has ended (waiting up to `wait` for that), or
// 202 with where to ask again.
Response pretestReply(Services& s, const AssignmentInfo& assignment, std::int64_t jobId, std::chrono::milliseconds wait)
{
    const auto run = s.labs.waitForRun(jobId, wait);
    if (!run) return apiError(http::status::not_found, "not_found", "the pretests' run was deleted");
    if (!isFinished(run->state)) {
        const std::string location =
            "/api/v1/assignments/" + std::to_string(assignment.id) + "/pretests/" + std::to_string(jobId);
        Response r = jsonResponse(http::status::accepted,
                                  {{"job_id", jobId}, {"state", jobStateName(run->state)}, {"location", location}});
        r.set(http::field::location, location);
        r.set(http::field::retry_after, "1");
        return r;
    }
    LabError failure;
    const auto judgement = s.labs.judgeRun(assignment, *run, true, failure);
    if (!judgement) return labErrorResponse(failure);
    nlohmann::json body = judgement->toJson();
    body["job_id"] = jobId;
    return jsonResponse(http::status::ok, body);
}

// The copy runs as a job of the student's on the job queue, named "pretest" (it is one of
// their runs), on whichever node claims it; the reply waits for it up to --lab-wait-seconds.
Response pretest(Services& s, Call& call)
{
    Response error;
    const auto view = studentAssignment(s, call, "run pretests", error);
    if (!view) return error;
    const auto copy = s.labs.store().copy(view->assignment.id, call.who().id);
    const auto hmf = copy ? s.models.hmf(copy->modelId) : std::nullopt;
    if (!hmf) return apiError(http::status::conflict, "conflict", "open the assignment first");
    JobRequest request;
    request.ownerId = call.who().id;
    request.modelId = copy->modelId;
    request.hmf = *hmf;
    const auto submitted = s.queue.submit(request);
    if (!submitted.id) return refusal(submitted.code, "the pretests cannot run: " + submitted.message);
    s.queue.store().label(*submitted.id, std::string("pretest"), std::nullopt);
    return pretestReply(s, view->assignment, *submitted.id, s.options.labWait);
}

// GET /assignments/{id}/pretests/{job}: a pretest answered 202 asks again here.
Response pretestOutcome(Services& s, Call& call)
{
    Response error;
    const auto view = studentAssignment(s, call, "run pretests", error);
    if (!view) return error;
    const auto copy = s.labs.store().copy(view->assignment.id, call.who().id);
    const auto jobId = parseId(call.params.path["job"]);
    const auto run = jobId ? s.queue.store().info(*jobId) : std::nullopt;
    // Only a run of the caller's own copy of this assignment.
    if (!copy || !run || run->ownerId != call.who().id || run->modelId != copy->modelId)
        return apiError(http::status::not_found, "not_found", "no such pretest run");
    return pretestReply(s, view->assignment, run->id, std::chrono::milliseconds(0));
}

Response handIn(Services& s, Call& call)
{
    Response error;
    const auto view = studentAssignment(s, call, "hand in", error);
    if (!view) return error;
    LabError failure;
    const auto receivedAt = std::chrono::duration_cast<std::chrono::seconds>(call.receivedAt.time_since_epoch()).count();
    const auto stored = s.labs.handIn(view->assignment, call.who(), receivedAt, failure);
    if (!stored) return labErrorResponse(failure);
    if (s.lti)
        s.lti->queueScore(view->assignment.id, call.who().id, stored->score, stored->maxScore,
                          "hand-in " + std::to_string(stored->attempt), receivedAt * 1000);
    return jsonResponse(http::status::created, LabService::handInJson(*stored, view->classView.isStaff()));
}

// What went, or goes, to the learning platforms' grade books: for the class's staff.
Response ltiScores(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (!view->classView.isStaff()) return apiError(http::status::forbidden, "forbidden", "the grades sent are for staff");
    std::map<std::int64_t, std::string> platformNames, userNames;
    for (const LtiPlatform& p : s.ltiPlatforms.listPlatforms()) platformNames[p.id] = p.name;
    protocol::LtiScoreList out;
    for (const LtiScore& score : s.ltiPlatforms.scoresOf(view->assignment.id)) {
        if (!userNames.count(score.userId)) {
            const auto user = s.users.find(score.userId);
            userNames[score.userId] = user ? user->username : "";
        }
        protocol::LtiScoreInfo info;
        info.id = score.id;
        info.platform = platformNames[score.platformId];
        info.user = {score.userId, userNames[score.userId]};
        info.scoreGiven = score.scoreGiven;
        info.scoreMaximum = score.scoreMaximum;
        info.state = score.state;
        info.attempts = score.attempts;
        info.nextAttemptAt = score.nextAttemptAt;
        info.lastError = score.lastError;
        info.createdAt = score.createdAt;
        info.deliveredAt = score.deliveredAt;
        out.scores.push_back(std::move(info));
    }
    return jsonResponse(http::status::ok, out);
}

Response listHandIns(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    std::optional<std::int64_t> student;
    if (view->classView.isStudent()) {
        student = call.who().id;
    } else if (const auto it = call.params.query.find("student"); it != call.params.query.end()) {
        student = parseId(it->second);
        if (!student) return apiError(http::status::bad_request, "bad_request", "student must be a user id");
    }
    nlohmann::json list = nlohmann::json::array();
    for (const HandIn& h : s.labs.store().handIns(view->assignment.id, student))
        list.push_back(LabService::handInJson(h, view->classView.isStaff()));
    return jsonResponse(http::status::ok, {{"handins", list}});
}

Response dashboard(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (!view->classView.isStaff()) return apiError(http::status::forbidden, "forbidden", "the dashboard is for staff");
    return jsonResponse(http::status::ok, s.labs.dashboard(view->assignment));
}

Response overlay(Services& s, Call& call)
{
    const auto view = visibleAssignment(s, call);
    if (!view) return labNotFound("assignment");
    if (!view->classView.isStaff()) return apiError(http::status::forbidden, "forbidden", "the overlay is for staff");
    const auto variable = call.params.query.find("variable");
    if (variable == call.params.query.end() || variable->second.empty())
        return apiError(http::status::bad_request, "bad_request", "give variable=NAME");
    std::size_t points = 500;
    if (const auto it = call.params.query.find("points"); it != call.params.query.end()) {
        const auto [end, ec] = std::from_chars(it->second.data(), it->second.data() + it->second.size(), points);
        if (ec != std::errc() || end != it->second.data() + it->second.size() || points < 2 || points > 10000)
            return apiError(http::status::bad_request, "bad_request", "points must be a whole number from 2 to 10000");
    }
    return jsonResponse(http::status::ok, s.labs.overlay(view->assignment, variable->second, points));
}

} // namespace

void addAssignmentRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/classes/{id}/assignments", true, createAssignment, RouteWork::Checks});
    routes.push_back({http::verb::get, "/classes/{id}/assignments", true, listAssignments});
    routes.push_back({http::verb::get, "/assignments/{id}", true, getAssignment});
    routes.push_back({http::verb::patch, "/assignments/{id}", true, updateAssignment, RouteWork::Checks});
    routes.push_back({http::verb::delete_, "/assignments/{id}", true, deleteAssignment});
    routes.push_back({http::verb::put, "/assignments/{id}/checks", true, putChecks});
    routes.push_back({http::verb::get, "/assignments/{id}/checks", true, getChecks});
    routes.push_back({http::verb::post, "/assignments/{id}/open", true, openAssignment});
    routes.push_back({http::verb::post, "/assignments/{id}/reset", true, resetCopy});
    routes.push_back({http::verb::post, "/assignments/{id}/pretest", true, pretest, RouteWork::Checks});
    routes.push_back({http::verb::get, "/assignments/{id}/pretests/{job}", true, pretestOutcome});
    routes.push_back({http::verb::post, "/assignments/{id}/handin", true, handIn, RouteWork::Checks});
    routes.push_back({http::verb::get, "/assignments/{id}/lti-scores", true, ltiScores});
    routes.push_back({http::verb::get, "/assignments/{id}/handins", true, listHandIns});
    routes.push_back({http::verb::get, "/assignments/{id}/dashboard", true, dashboard});
    routes.push_back({http::verb::get, "/assignments/{id}/overlay", true, overlay});
}

} // namespace tlmhub::server
