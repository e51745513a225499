// /studies: submit, list, status, cancel or delete, resume, results as one table, a run's full result,
// a sensitivity study's bands (docs/studies.md).
#include "server/api/ApiSupport.h"
#include "server/api/IdempotentPost.h"

#include "server/auth/AccessPolicy.h"
#include "server/http/HeaderValues.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"
#include "server/labs/StudyLock.h"
#include "server/store/ResultBlob.h"
#include "server/studies/StudyService.h"

#include <charconv>

namespace tlmhub::server {

namespace {

// A study the caller may see: own, or any for an administrator.
std::optional<StudyInfo> visibleStudy(Services& s, const User& who, const std::string& idText)
{
    const auto id = parseId(idText);
    if (!id) return std::nullopt;
    auto study = s.studies.store().info(*id);
    if (!study || !canControlJob(who, study->ownerId)) return std::nullopt;
    return study;
}

Response notFound() { return apiError(http::status::not_found, "not_found", "no such study"); }

std::string queryValue(const Call& call, const std::string& key, const std::string& fallback)
{
    const auto it = call.params.query.find(key);
    return it == call.params.query.end() ? fallback : it->second;
}

Created createStudy(Services& s, Call& call)
{
    nlohmann::json body;
    Response error;
    if (!readJsonBody(call, "StudyCreate", body, error)) return {error, std::nullopt};
    std::string hmf;
    if (body.contains("model_id") && body["model_id"].is_number_integer()) {
        const auto model = readableModel(s, call.who(), body["model_id"].get<std::int64_t>());
        if (!model) return {apiError(http::status::not_found, "not_found", "no such model"), std::nullopt};
        hmf = s.models.hmf(model->id).value_or("");
        // A student's copy is studied only in the parameters its assignment lets them change.
        if (const CopyAccess access = copyAccess(s.labs.store(), call.who(), model->id); access.lock) {
            StudyRequest request;
            std::string why;
            if (!parseStudyRequest(body, request, why))
                return {apiError(http::status::bad_request, "bad_request", why), std::nullopt};
            if (const std::string problem = studyLockProblem(request, *access.lock); !problem.empty())
                return {apiError(http::status::forbidden, "locked", problem), std::nullopt};
        }
    } else if (body.contains("hmf") && body["hmf"].is_string()) {
        hmf = body["hmf"].get<std::string>();
    }
    const auto submitted = s.studies.submit(call.who().id, body, hmf);
    if (!submitted.id) return {refusal(submitted.code, submitted.message), std::nullopt};
    return {jsonResponse(http::status::created, {{"id", *submitted.id}, {"runs_total", submitted.runsTotal}}), submitted.id};
}

Response submitStudy(Services& s, Call& call)
{
    return idempotentPost(
        s, call, "POST /studies", [&] { return createStudy(s, call); },
        [&](std::int64_t id) {
            const auto study = s.studies.store().info(id);
            if (!study) return apiError(http::status::gone, "gone", "the study this Idempotency-Key made was deleted");
            return jsonResponse(http::status::created, {{"id", id}, {"runs_total", study->runsTotal}});
        });
}

Response listStudies(Services& s, Call& call)
{
    nlohmann::json studies = nlohmann::json::array();
    for (const StudyInfo& study : s.studies.store().listForOwner(call.who().id))
        studies.push_back(StudyService::infoJson(study));
    return jsonResponse(http::status::ok, {{"studies", studies}});
}

Response getStudy(Services& s, Call& call)
{
    const auto study = visibleStudy(s, call.who(), call.params.path["id"]);
    if (!study) return notFound();
    return jsonResponse(http::status::ok, StudyService::infoJson(*study));
}

Response cancelOrDeleteStudy(Services& s, Call& call)
{
    const auto study = visibleStudy(s, call.who(), call.params.path["id"]);
    if (!study) return notFound();
    // A queued or running study is cancelled (and kept); a finished one is deleted with its
    // runs, which frees the owner's storage quota.
    if (study->state == JobState::Queued || study->state == JobState::Running) {
        s.studies.cancel(study->id);
        const auto now = s.studies.store().info(study->id);
        if (now && now->state == JobState::Cancelled) return jsonResponse(http::status::ok, StudyService::infoJson(*now));
        return jsonResponse(http::status::accepted, {{"state", "cancelling"}});
    }
    s.studies.store().remove(study->id);
    return noContent();
}

// An interrupted or cancelled study runs the runs it lacks (409 in any other state).
Response resumeStudy(Services& s, Call& call)
{
    const auto study = visibleStudy(s, call.who(), call.params.path["id"]);
    if (!study) return notFound();
    const auto resumed = s.studies.resume(*study);
    if (!resumed.id) return refusal(resumed.code, resumed.message);
    const auto now = s.studies.store().info(study->id);
    return jsonResponse(http::status::accepted, StudyService::infoJson(now ? *now : *study));
}

Response studyResults(Services& s, Call& call)
{
    const auto study = visibleStudy(s, call.who(), call.params.path["id"]);
    if (!study) return notFound();
    const auto table = s.studies.table(study->id);
    if (!table) return apiError(http::status::internal_server_error, "internal", "the study's request is unreadable");
    const std::string format = queryValue(call, "format", "json");
    if (format == "csv") {
        Response res = textResponse(http::status::ok, StudyService::tableCsv(*table), "text/csv");
        res.set(http::field::content_disposition, attachmentDisposition("study-" + std::to_string(study->id) + ".csv"));
        return res;
    }
    if (format != "json") return apiError(http::status::bad_request, "bad_request", "format must be csv or json");
    nlohmann::json errors = nlohmann::json::object();
    for (const auto& [run, message] : table->errors) errors[std::to_string(run)] = message;
    return jsonResponse(http::status::ok, {{"columns", table->columns}, {"rows", table->rows}, {"nodes", table->nodes}, {"errors", errors}});
}

Response runResults(Services& s, Call& call)
{
    const auto study = visibleStudy(s, call.who(), call.params.path["id"]);
    if (!study) return notFound();
    const std::string indexText = call.params.path["index"];
    std::int64_t index = -1;
    const auto [end, ec] = std::from_chars(indexText.data(), indexText.data() + indexText.size(), index);
    const bool isIndex = ec == std::errc() && end == indexText.data() + indexText.size() && index >= 0;
    const auto blob = isIndex ? s.studies.store().runResult(study->id, index) : std::nullopt;
    if (!blob)
        return apiError(http::status::not_found, "not_found",
                        "no stored result of run " + indexText + " (a study keeps them with outputs.full)");
    const std::vector<std::string> variables = commaSeparated(queryValue(call, "variables", ""));
    const auto table = decodeResult(*blob, variables);
    if (!table) return apiError(http::status::internal_server_error, "internal", "the run's result is unreadable");
    for (const std::string& v : variables)
        if (!table->hasColumn(v)) return apiError(http::status::bad_request, "bad_request", "no logged variable '" + v + "'");
    const std::string format = queryValue(call, "format", "json");
    if (format == "csv") {
        Response res = textResponse(http::status::ok, table->toCsv(variables), "text/csv");
        res.set(http::field::content_disposition,
                attachmentDisposition("study-" + std::to_string(study->id) + "-run-" + indexText + ".csv"));
        return res;
    }
    if (format != "json") return apiError(http::status::bad_request, "bad_request", "format must be csv or json");
    return jsonResponse(http::status::ok, table->toJson(variables));
}

Response studyBands(Services& s, Call& call)
{
    const auto study = visibleStudy(s, call.who(), call.params.path["id"]);
    if (!study) return notFound();
    const std::string format = queryValue(call, "format", "json");
    if (format != "csv" && format != "json") return apiError(http::status::bad_request, "bad_request", "format must be csv or json");
    if (format == "csv") {
        const auto csv = s.studies.bandsCsv(*study);
        if (!csv) return apiError(http::status::conflict, "conflict", "the study has no bands (a finished sensitivity study has)");
        return textResponse(http::status::ok, *csv, "text/csv");
    }
    const auto json = s.studies.bandsJson(*study);
    if (!json) return apiError(http::status::conflict, "conflict", "the study has no bands (a finished sensitivity study has)");
    return jsonResponse(http::status::ok, *json);
}

} // namespace

void addStudyRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/studies", true, submitStudy});
    routes.push_back({http::verb::get, "/studies", true, listStudies});
    routes.push_back({http::verb::get, "/studies/{id}", true, getStudy});
    routes.push_back({http::verb::delete_, "/studies/{id}", true, cancelOrDeleteStudy});
    routes.push_back({http::verb::post, "/studies/{id}/resume", true, resumeStudy});
    routes.push_back({http::verb::get, "/studies/{id}/results", true, studyResults, RouteWork::LargeReply});
    routes.push_back({http::verb::get, "/studies/{id}/runs/{index}/results", true, runResults, RouteWork::LargeReply});
    routes.push_back({http::verb::get, "/studies/{id}/bands", true, studyBands});
}

} // namespace tlmhub::server
