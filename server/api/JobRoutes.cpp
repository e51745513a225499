// /jobs: submit, list, status, cancel, re-run, results as CSV or JSON.
#include "server/api/ApiSupport.h"
#include "server/api/IdempotentPost.h"

#include "server/app/ServerOptions.h"
#include "server/auth/AccessPolicy.h"
#include "server/http/HeaderValues.h"
#include "server/jobs/RunParameterDifferences.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"
#include "server/store/ModelName.h"

#include <map>


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

// A run live.record stored keeps its session's changes in its request (JobRequest::live).
std::optional<nlohmann::json> recordedSession(JobStore& store, std::int64_t id)
{
    const auto text = store.requestText(id);
    // Most runs are not recordings: their request (with the whole model) is not parsed.
    if (!text || text->find("\"live\":") == std::string::npos) return std::nullopt;
    JobRequest request;
    if (!JobRequest::fromJson(nlohmann::json::parse(*text, nullptr, false), request)) return std::nullopt;
    return request.live;
}

Created createJob(Services& s, Call& call)
{
    protocol::JobRequest body;
    Response error;
    if (!readBody(call, "JobRequest", body, error)) return {error, std::nullopt};
    JobRequest request;
    request.ownerId = call.who().id;
    if (body.modelId) {
        const auto model = readableModel(s, call.who(), *body.modelId);
        if (!model) return {apiError(http::status::not_found, "not_found", "no such model"), std::nullopt};
        request.modelId = model->id;
        request.hmf = s.models.hmf(model->id).value_or("");
    } else if (body.hmf) {
        request.hmf = *body.hmf;
    } else {
        return {apiError(http::status::bad_request, "bad_request", "give model_id or hmf"), std::nullopt};
    }
    for (const auto& [name, value] : body.parameters.value_or(std::map<std::string, nlohmann::json>{}))
        request.parameters[name] = value.is_string() ? value.get<std::string>() : value.dump();
    // A student's copy runs with the overrides its assignment lets them change.
    if (request.modelId) {
        const CopyAccess access = copyAccess(s.labs.store(), call.who(), *request.modelId);
        if (access.lock) {
            for (const auto& [name, value] : request.parameters)
                if (const std::string problem = access.lock->valueProblem(name, value); !problem.empty())
                    return {apiError(http::status::forbidden, "locked", problem), std::nullopt};
            request.settingsFixed = true;
        }
    }
    if (body.start) request.settings.start = *body.start;
    if (body.step) request.settings.step = *body.step;
    if (body.stop) request.settings.stop = *body.stop;
    if (body.logSamples) request.settings.logSamples = static_cast<std::size_t>(*body.logSamples);
    request.keep = body.keep.value_or(true);
    const auto submitted = s.queue.submit(request);
    if (!submitted.id) return {refusal(submitted.code, submitted.message), std::nullopt};
    return {jsonResponse(http::status::created, s.queue.store().info(*submitted.id)->toJson()), submitted.id};
}

Response submitJob(Services& s, Call& call)
{
    return idempotentPost(
        s, call, "POST /jobs", [&] { return createJob(s, call); },
        [&](std::int64_t id) {
            const auto job = s.queue.store().info(id);
            if (!job) return apiError(http::status::gone, "gone", "the job this Idempotency-Key made was deleted");
            return jsonResponse(http::status::created, job->toJson());
        });
}

constexpr int kDefaultHistoryPage = 20;
constexpr int kMaxHistoryPage = 100;
// Differing parameters listed per run: a restructured model may differ in thousands.
constexpr std::size_t kMaxDifferingParameters = 100;

// GET /jobs?model_id=ID[&limit=N][&before=JOB]: the model's runs, newest first, as GET
// /jobs/{id} lets the caller see them: all of them for an administrator and for the staff of
// a student's copy, else the caller's own. The next page: before = the last id of this one.
// Each run says which parameter values it used that the model's text no longer says.
Response modelHistory(Services& s, Call& call)
{
    const auto& q = call.params.query;
    const auto modelId = parseId(q.at("model_id"));
    if (!modelId) return apiError(http::status::bad_request, "bad_request", "model_id must be a model's id");
    int limit = kDefaultHistoryPage;
    if (q.count("limit")) {
        const auto n = parseId(q.at("limit"));
        if (!n || *n > kMaxHistoryPage)
            return apiError(http::status::bad_request, "bad_request",
                            "limit must be 1 to " + std::to_string(kMaxHistoryPage));
        limit = static_cast<int>(*n);
    }
    std::optional<std::int64_t> before;
    if (q.count("before") && !(before = parseId(q.at("before"))))
        return apiError(http::status::bad_request, "bad_request", "before must be a job's id");
    const User& who = call.who();
    const bool everyones = who.role == kRoleAdmin ||
                           copyAccess(s.labs.store(), who, *modelId).kind == CopyAccess::Kind::Read;
    if (!everyones && !readableModel(s, who, *modelId)) return apiError(http::status::not_found, "not_found", "no such model");
    std::map<std::int64_t, std::string> owners;
    RunParameterDifferences differences([&] { return s.models.hmf(*modelId).value_or(""); }, s.options.limits.model);
    nlohmann::json out = nlohmann::json::array();
    for (const JobInfo& job : s.queue.store().listForModel(*modelId, everyones ? std::nullopt : std::optional(who.id),
                                                            before, limit)) {
        auto owner = owners.find(job.ownerId);
        if (owner == owners.end()) {
            const auto user = s.users.find(job.ownerId);
            owner = owners.emplace(job.ownerId, user ? user->username : std::string()).first;
        }
        nlohmann::json entry = job.toJson();
        entry["owner"] = owner->second;
        std::map<std::string, std::string> used;
        if (job.usedParameters) used = *job.usedParameters;
        else if (const auto request = s.queue.store().request(job.id)) used = differences.usedBy(*request);
        bool truncated = false;
        entry["differing_parameters"] = differences.differing(used, kMaxDifferingParameters, truncated);
        if (truncated) entry["differing_parameters_truncated"] = true;
        out.push_back(std::move(entry));
    }
    return jsonResponse(http::status::ok, out);
}

Response listJobs(Services& s, Call& call)
{
    if (call.params.query.count("model_id")) return modelHistory(s, call);
    nlohmann::json out = nlohmann::json::array();
    for (const JobInfo& job : s.queue.store().listForOwner(call.who().id)) out.push_back(job.toJson());
    return jsonResponse(http::status::ok, out);
}

// PATCH /jobs/{id} {name?, pinned?}: the owner names or pins a run.
Response labelJob(Services& s, Call& call)
{
    protocol::JobUpdate body;
    Response error;
    if (!readBody(call, "JobUpdate", body, error)) return error;
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    if (!canControlJob(call.who(), job->ownerId))
        return apiError(http::status::forbidden, "forbidden", "only the owner names or pins a run");
    if (body.name && !body.name->empty())
        if (const std::string problem = modelNameProblem(*body.name); !problem.empty())
            return apiError(http::status::bad_request, "bad_request", "run name: " + problem);
    if (!s.queue.store().label(job->id, body.name, body.pinned))
        return apiError(http::status::not_found, "not_found", "no such job");
    return jsonResponse(http::status::ok, s.queue.store().info(job->id)->toJson());
}

Response getJob(Services& s, Call& call)
{
    auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    job->live = recordedSession(s.queue.store(), job->id);
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

// 410 for a run whose results are gone: given once (keep: false), or dropped for newer runs.
Response resultsGone(bool keep)
{
    return keep ? apiError(http::status::gone, "gone",
                           "the run's results were dropped: a model keeps the results of its newest unpinned "
                           "runs only (--max-unpinned-runs-per-model); pin a run to keep them")
                : apiError(http::status::gone, "gone",
                           "the run was submitted with keep: false, and its results were given once already");
}

bool keptRun(Services& s, std::int64_t id)
{
    return s.queue.store().request(id).value_or(JobRequest{}).keep;
}

Response jobResults(Services& s, Call& call)
{
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    if (job->state != JobState::Done)
        return apiError(http::status::conflict, "conflict",
                        std::string("the job has no results (state ") + jobStateName(job->state) + ")");
    const bool keep = keptRun(s, job->id);
    if (job->resultsDropped) return resultsGone(keep);
    const auto& q = call.params.query;
    const std::vector<std::string> variables = q.count("variables") ? commaSeparated(q.at("variables")) : std::vector<std::string>{};
    const auto table = s.queue.results().result(job->id, variables);
    if (!table) return apiError(http::status::not_found, "not_found", "the job's results are gone");
    for (const std::string& v : variables)
        if (!table->hasColumn(v))
            return apiError(http::status::bad_request, "bad_request", "no logged variable '" + v + "'");
    const std::string format = q.count("format") ? q.at("format") : "json";
    if (format != "csv" && format != "json")
        return apiError(http::status::bad_request, "bad_request", "format must be csv or json");
    // Given once: of reads racing for them, only the one that drops them answers them.
    if (!keep && !s.queue.store().dropResults(job->id)) return resultsGone(keep);
    if (format == "csv") {
        Response res = textResponse(http::status::ok, table->toCsv(variables), "text/csv");
        res.set(http::field::content_disposition, attachmentDisposition("job-" + std::to_string(job->id) + ".csv"));
        return res;
    }
    return jsonResponse(http::status::ok, table->toJson(variables));
}

// GET /jobs/{id}/variables: the run's logged variables with their units, without their data
// (what a script labels its columns with; read before the results of a keep: false run).
Response jobVariables(Services& s, Call& call)
{
    const auto job = visibleJob(s, call.who(), call.params.path["id"]);
    if (!job) return apiError(http::status::not_found, "not_found", "no such job");
    if (job->state != JobState::Done)
        return apiError(http::status::conflict, "conflict",
                        std::string("the job has no results (state ") + jobStateName(job->state) + ")");
    const auto table = job->resultsDropped ? std::nullopt : s.queue.results().result(job->id, {});
    if (!table) return resultsGone(keptRun(s, job->id));
    nlohmann::json variables = nlohmann::json::array();
    for (const ResultColumn& column : table->columns) variables.push_back({{"name", column.name}, {"unit", column.unit}});
    return jsonResponse(http::status::ok, {{"variables", std::move(variables)}});
}

} // namespace

void addJobRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::post, "/jobs", true, submitJob});
    routes.push_back({http::verb::get, "/jobs", true, listJobs});
    routes.push_back({http::verb::get, "/jobs/{id}", true, getJob});
    routes.push_back({http::verb::patch, "/jobs/{id}", true, labelJob});
    routes.push_back({http::verb::delete_, "/jobs/{id}", true, cancelOrDeleteJob});
    routes.push_back({http::verb::post, "/jobs/{id}/rerun", true, rerunJob});
    routes.push_back({http::verb::get, "/jobs/{id}/results", true, jobResults, RouteWork::LargeReply});
    routes.push_back({http::verb::get, "/jobs/{id}/variables", true, jobVariables});
}

} // namespace tlmhub::server
