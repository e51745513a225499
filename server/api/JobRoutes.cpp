// /jobs: submit, list, status, cancel, re-run, results as CSV or JSON.
#include "server/api/ApiSupport.h"

#include "server/auth/AccessPolicy.h"
#include "server/http/HeaderValues.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"


namespace tlmhub::server {

namespace {

// A job the caller may see: own, or any for an admin, or a run of a student's copy for the
// staff of its class.
std::optional<JobInfo> visibleJob(Services& s, const User& who, const std::string& idText)
{
    const auto id = parseId(idText);
    if (!id) return std::nullopt;
    auto job = s.queue.store().info(*id);
    if (!job) return std::nullopt;
    if (canRead(who, job->ownerId, false)) return job;
    if (job->modelId && copyAccess(s.labs.store(), who, *job->modelId).kind == CopyAccess::Kind::Read) return job;
    return std::nullopt;
}

Response submitJob(Services& s, Call& call)
{
    protocol::JobRequest body;
    Response error;
    if (!readBody(call, "JobRequest", body, error)) return error;
    JobRequest request;
    request.ownerId = call.who().id;
    if (body.modelId) {
        const auto model = readableModel(s, call.who(), *body.modelId);
        if (!model) return apiError(http::status::not_found, "not_found", "no such model");
        request.modelId = model->id;
        request.hmf = s.models.hmf(model->id).value_or("");
    } else if (body.hmf) {
        request.hmf = *body.hmf;
    } else {
        return apiError(http::status::bad_request, "bad_request", "give model_id or hmf");
    }
    for (const auto& [name, value] : body.parameters.value_or(std::map<std::string, nlohmann::json>{}))
        request.parameters[name] = value.is_string() ? value.get<std::string>() : value.dump();
    // A student's copy runs with the overrides its assignment lets them change.
    if (request.modelId) {
        const CopyAccess access = copyAccess(s.labs.store(), call.who(), *request.modelId);
        if (access.lock) {
            for (const auto& [name, value] : request.parameters)
                if (const std::string problem = access.lock->valueProblem(name, value); !problem.empty())
                    return apiError(http::status::forbidden, "locked", problem);
            request.settingsFixed = true;
        }
    }
    if (body.start) request.settings.start = *body.start;
    if (body.step) request.settings.step = *body.step;
    if (body.stop) request.settings.stop = *body.stop;
    if (body.logSamples) request.settings.logSamples = static_cast<std::size_t>(*body.logSamples);
    const auto submitted = s.queue.submit(request);
    if (!submitted.id) return refusal(submitted.code, submitted.message);
    return jsonResponse(http::status::created, s.queue.store().info(*submitted.id)->toJson());
}

Response listJobs(Services& s, Call& call)
{
    nlohmann::json out = nlohmann::json::array();
    for (const JobInfo& job : s.queue.store().listForOwner(call.who().id)) out.push_back(job.toJson());
    return jsonResponse(http::status::ok, out);
}

Response getJob(Services& s, Call& call)
{
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    return jsonResponse(http::status::ok, job->toJson());
}

Response cancelOrDeleteJob(Services& s, Call& call)
{
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    if (!canControlJob(call.who(), job->ownerId))
        return apiError(http::status::forbidden, "forbidden", "only the owner cancels or deletes a job");
    // A waiting or running job is cancelled (and kept); a finished one is deleted with its
    // results, which frees the owner's storage quota.
    if (job->state == JobState::Queued || job->state == JobState::Running) {
        s.queue.cancel(job->id);
        return jsonResponse(http::status::ok, s.queue.store().info(job->id)->toJson());
    }
    s.queue.store().remove(job->id);
    return noContent();
}

Response rerunJob(Services& s, Call& call)
{
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job || !canRerunJob(call.who(), job->ownerId))
        return apiError(http::status::not_found, "not_found", "no such job of yours");
    const auto request = s.queue.store().request(job->id);
    if (!request) return apiError(http::status::not_found, "not_found", "the job's input is gone");
    const auto submitted = s.queue.submit(*request);
    if (!submitted.id) return refusal(submitted.code, submitted.message);
    return jsonResponse(http::status::created, s.queue.store().info(*submitted.id)->toJson());
}

Response jobResults(Services& s, Call& call)
{
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    if (job->state != JobState::Done)
        return apiError(http::status::conflict, "conflict",
                        std::string("the job has no results (state ") + jobStateName(job->state) + ")");
    const auto& q = call.params.query;
    const std::vector<std::string> variables = q.count("variables") ? commaSeparated(q.at("variables")) : std::vector<std::string>{};
    const auto table = s.queue.results().result(job->id, variables);
    if (!table) return apiError(http::status::not_found, "not_found", "the job's results are gone");
    for (const std::string& v : variables)
        if (!table->hasColumn(v))
            return apiError(http::status::bad_request, "bad_request", "no logged variable '" + v + "'");
    const std::string format = q.count("format") ? q.at("format") : "json";
    if (format == "csv") {
        Response res = textResponse(http::status::ok, table->toCsv(variables), "text/csv");
        res.set(http::field::content_disposition, attachmentDisposition("job-" + std::to_string(job->id) + ".csv"));
        return res;
    }
    if (format != "json") return apiError(http::status::bad_request, "bad_request", "format must be csv or json");
    return jsonResponse(http::status::ok, table->toJson(variables));
}

} // namespace

void addJobRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/jobs", true, submitJob});
    routes.push_back({http::verb::get, "/jobs", true, listJobs});
    routes.push_back({http::verb::get, "/jobs/{id}", true, getJob});
    routes.push_back({http::verb::delete_, "/jobs/{id}", true, cancelOrDeleteJob});
    routes.push_back({http::verb::post, "/jobs/{id}/rerun", true, rerunJob});
    routes.push_back({http::verb::get, "/jobs/{id}/results", true, jobResults, RouteWork::LargeReply});
}

} // namespace tlmhub::server
