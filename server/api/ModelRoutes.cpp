// /models: list, create (upload .hmf, JSON, duplicate), read (.hmf or JSON), update, delete.
#include "server/api/ApiSupport.h"
#include "server/api/CoreErrorCodes.h"

#include "server/auth/AccessPolicy.h"
#include "server/edit/ModelJson.h"
#include "server/http/HeaderValues.h"
#include "server/app/ServerOptions.h"
#include "server/jobs/ModelLimits.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"
#include "server/store/ModelName.h"

#include "core/hmf/HmfLoader.h"
#include "core/hmf/HmfSaver.h"

namespace tlmhub::server {

namespace {

// Loads `hmf` within the server's model limits and evaluates its parameters; on failure
// `error` holds the 400 response naming the problem.
std::unique_ptr<System> checkedModel(Services& s, const std::string& hmf, Response& error)
{
    LoadedModel loaded = loadUntrustedModel(hmf, s.options.limits.model, "", "uploaded model");
    if (const Status status = loaded.status(); !status) {
        error = apiError(http::status::bad_request, protocolErrorCode(status.code()), status.message());
        return nullptr;
    }
    if (const std::string problem = firstParameterProblem(*loaded.root); !problem.empty()) {
        error = apiError(http::status::bad_request, "invalid_parameter", "uploaded model: " + problem);
        return nullptr;
    }
    return std::move(loaded.root);
}

// On a refused name `error` holds the 400 response saying why.
bool acceptableName(const std::string& name, Response& error)
{
    const std::string problem = modelNameProblem(name);
    if (problem.empty()) return true;
    error = apiError(http::status::bad_request, "bad_request", "model name: " + problem);
    return false;
}

// A new model gets Hopsan's defaults for a new model, so that its first run works as is.
std::string emptyModelHmf(const std::string& name)
{
    System root;
    root.setNameRaw(sanitizeName(name));
    root.startTime = 0.0;
    root.stopTime = 10.0;
    root.desiredTimestep = 1e-3;
    root.requestedLogSamples = 2048;
    return saveHmfString(root);
}

Response listModels(Services& s, Call& call)
{
    nlohmann::json out = nlohmann::json::array();
    for (const ModelSummary& m : s.models.listVisibleTo(call.who())) out.push_back(modelSummaryJson(m));
    return jsonResponse(http::status::ok, out);
}

Response created(Services& s, std::optional<std::int64_t> id)
{
    if (!id) return apiError(http::status::not_found, "not_found", "the account that would own the model does not exist");
    return jsonResponse(http::status::created, modelSummaryJson(*s.models.summary(*id)));
}

Response createModel(Services& s, Call& call)
{
    Response error;
    if (isXmlRequest(call.request)) {
        const std::string& hmf = call.request.body();
        auto root = checkedModel(s, hmf, error);
        if (!root) return error;
        const auto nameParam = call.params.query.find("name");
        const std::string name = nameParam != call.params.query.end() && !nameParam->second.empty()
                                     ? nameParam->second : root->name();
        if (!acceptableName(name, error)) return error;
        return created(s, s.models.create(call.who().id, name, hmf, false));
    }
    protocol::ModelCreate body;
    if (!readBody(call, "ModelCreate", body, error)) return error;
    const std::string& name = body.name;
    if (!acceptableName(name, error)) return error;
    if (body.copyOf) {
        const auto source = readableModel(s, call.who(), *body.copyOf);
        if (!source) return apiError(http::status::not_found, "not_found", "no such model to copy");
        return created(s, s.models.create(call.who().id, name, *s.models.hmf(source->id), false));
    }
    if (body.hmf) {
        if (!checkedModel(s, *body.hmf, error)) return error;
        return created(s, s.models.create(call.who().id, name, *body.hmf, false));
    }
    return created(s, s.models.create(call.who().id, name, emptyModelHmf(name), false));
}

Response getModel(Services& s, Call& call)
{
    const auto id = parseId(call.params.path["id"]);
    const auto summary = id ? readableModel(s, call.who(), *id) : std::nullopt;
    if (!summary) return apiError(http::status::not_found, "not_found", "no such model");
    const std::string hmf = s.models.hmf(summary->id).value_or("");
    if (wantsXml(call)) {
        Response res = textResponse(http::status::ok, hmf, "application/xml");
        res.set(http::field::content_disposition, attachmentDisposition(summary->name + ".hmf"));
        return res;
    }
    nlohmann::json out = modelSummaryJson(*summary);
    out["writable"] = writableModel(s, call.who(), *summary);
    LoadedModel loaded = loadHmfString(hmf, "", summary->name);
    if (loaded.root) out["model"] = describeModel(*loaded.root, summary->name);
    else out["load_error"] = loaded.firstError();
    return jsonResponse(http::status::ok, out);
}

Response updateModel(Services& s, Call& call)
{
    const auto id = parseId(call.params.path["id"]);
    const auto summary = id ? readableModel(s, call.who(), *id) : std::nullopt;
    if (!summary) return apiError(http::status::not_found, "not_found", "no such model");
    if (!writableModel(s, call.who(), *summary))
        return apiError(http::status::forbidden, "forbidden",
                        "this model is read-only for you (duplicate it to change it)");
    Response error;
    std::optional<std::string> name, hmf;
    if (isXmlRequest(call.request)) {
        hmf = call.request.body();
    } else {
        protocol::ModelUpdate body;
        if (!readBody(call, "ModelUpdate", body, error)) return error;
        name = body.name;
        hmf = body.hmf;
    }
    if (name && !acceptableName(*name, error)) return error;
    if (hmf && !checkedModel(s, *hmf, error)) return error;
    if (const CopyAccess access = copyAccess(s.labs.store(), call.who(), summary->id); access.lock) {
        if (name && *name != summary->name)
            return apiError(http::status::forbidden, "locked", "an assignment's copy keeps its name");
        if (hmf) {
            const std::string problem = access.lock->changeProblem(s.models.hmf(summary->id).value_or(""), *hmf,
                                                                   s.options.limits.model);
            if (!problem.empty()) return apiError(http::status::forbidden, "locked", problem);
        }
    }
    s.models.update(summary->id, name, hmf);
    return jsonResponse(http::status::ok, modelSummaryJson(*s.models.summary(summary->id)));
}

Response deleteModel(Services& s, Call& call)
{
    const auto id = parseId(call.params.path["id"]);
    const auto summary = id ? readableModel(s, call.who(), *id) : std::nullopt;
    if (!summary) return apiError(http::status::not_found, "not_found", "no such model");
    if (s.labs.store().copyByModel(summary->id))
        return apiError(http::status::conflict, "assignment_copy",
                        "this is your copy of an assignment: reset it to the template instead of deleting it");
    if (!writableModel(s, call.who(), *summary))
        return apiError(http::status::forbidden, "forbidden", "this model is read-only for you");
    s.models.remove(summary->id);
    return noContent();
}

} // namespace

void addModelRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/models", true, listModels});
    routes.push_back({http::verb::post, "/models", true, createModel});
    routes.push_back({http::verb::get, "/models/{id}", true, getModel, RouteWork::LargeReply});
    routes.push_back({http::verb::put, "/models/{id}", true, updateModel});
    routes.push_back({http::verb::delete_, "/models/{id}", true, deleteModel});
}

} // namespace tlmhub::server
