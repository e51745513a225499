// /handins/{id}: a hand-in with its checks, its frozen model, comments and the teacher's grade
// (docs/labs.md).
#include "server/api/ApiSupport.h"

#include "server/api/LabSupport.h"
#include "server/auth/lti/LtiTool.h"
#include "server/http/HeaderValues.h"
#include "server/store/UnixTime.h"

namespace tlmhub::server {

namespace {

struct HandInView {
    HandIn handIn;
    AssignmentView assignment;
};

// The hand-in of the path: its student (still in the class) and the class's staff see it.
std::optional<HandInView> visibleHandIn(Services& s, const Call& call)
{
    const auto it = call.params.path.find("id");
    const auto id = it == call.params.path.end() ? std::nullopt : parseId(it->second);
    auto handIn = id ? s.labs.store().handIn(*id) : std::nullopt;
    if (!handIn) return std::nullopt;
    auto assignment = assignmentFor(s.labs.store(), call.who(), handIn->assignmentId, unixNow());
    if (!assignment) return std::nullopt;
    if (assignment->classView.isStudent() && handIn->studentId != call.who().id) return std::nullopt;
    return HandInView{std::move(*handIn), std::move(*assignment)};
}

nlohmann::json commentJson(const HandInComment& c)
{
    return {{"id", c.id},
            {"author", {{"id", c.authorId}, {"username", c.authorName}}},
            {"text", c.text},
            {"created_at", c.createdAt}};
}

Response getHandIn(Services& s, Call& call)
{
    const auto view = visibleHandIn(s, call);
    if (!view) return labNotFound("hand-in");
    return jsonResponse(http::status::ok, LabService::handInJson(view->handIn, view->assignment.classView.isStaff()));
}

Response handInModel(Services& s, Call& call)
{
    const auto view = visibleHandIn(s, call);
    if (!view) return labNotFound("hand-in");
    Response res = textResponse(http::status::ok, view->handIn.hmf, "application/xml");
    res.set(http::field::content_disposition,
            attachmentDisposition("handin-" + std::to_string(view->handIn.id) + ".hmf"));
    return res;
}

Response listComments(Services& s, Call& call)
{
    const auto view = visibleHandIn(s, call);
    if (!view) return labNotFound("hand-in");
    nlohmann::json list = nlohmann::json::array();
    for (const HandInComment& c : s.labs.store().comments(view->handIn.id)) list.push_back(commentJson(c));
    return jsonResponse(http::status::ok, {{"comments", list}});
}

Response addComment(Services& s, Call& call)
{
    const auto view = visibleHandIn(s, call);
    if (!view) return labNotFound("hand-in");
    const ClassView& theClass = view->assignment.classView;
    if (!theClass.isStaff()) return apiError(http::status::forbidden, "forbidden", "only teachers and assistants comment");
    if (theClass.info.archived) return labArchived();
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "CommentCreate", body, error)) return error;
    const auto id = s.labs.store().addComment(view->handIn.id, call.who().id, body["text"].get<std::string>());
    if (!id) return labNotFound("hand-in");
    for (const HandInComment& c : s.labs.store().comments(view->handIn.id))
        if (c.id == *id) return jsonResponse(http::status::created, commentJson(c));
    return labNotFound("comment");
}

Response setGrade(Services& s, Call& call)
{
    const auto view = visibleHandIn(s, call);
    if (!view) return labNotFound("hand-in");
    const ClassView& theClass = view->assignment.classView;
    if (!theClass.isTeacher()) return apiError(http::status::forbidden, "forbidden", "only the class's teacher grades");
    if (theClass.info.archived) return labArchived();
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "GradeUpdate", body, error)) return error;
    const std::optional<double> grade = body["grade"].is_null() ? std::nullopt : std::optional(body["grade"].get<double>());
    s.labs.store().setGrade(view->handIn.id, grade, call.who().id);
    // The platforms' grade books follow the gradebook: the grade of the student's latest hand-in,
    // else its score.
    const auto attempts = s.labs.store().handIns(view->handIn.assignmentId, view->handIn.studentId);
    const bool latest = std::none_of(attempts.begin(), attempts.end(),
                                     [&](const HandIn& h) { return h.attempt > view->handIn.attempt; });
    if (s.lti && latest)
        s.lti->queueScore(view->handIn.assignmentId, view->handIn.studentId, grade.value_or(view->handIn.score),
                          view->handIn.maxScore, grade ? "graded by the teacher" : "hand-in " + std::to_string(view->handIn.attempt),
                          std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
                              .count());
    return jsonResponse(http::status::ok, LabService::handInJson(*s.labs.store().handIn(view->handIn.id), true));
}

} // namespace

void addHandInRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/handins/{id}", true, getHandIn});
    routes.push_back({http::verb::get, "/handins/{id}/model", true, handInModel});
    routes.push_back({http::verb::get, "/handins/{id}/comments", true, listComments});
    routes.push_back({http::verb::post, "/handins/{id}/comments", true, addComment});
    routes.push_back({http::verb::put, "/handins/{id}/grade", true, setGrade});
}

} // namespace tlmhub::server
