// /models/{id}/fmu: a stored model as an FMI 2.0 co-simulation FMU (docs/fmu.md), and the
// interface that FMU would have, so a client can show it before the download.
#include "server/api/ApiSupport.h"
#include "server/api/CoreErrorCodes.h"

#include "server/app/ServerOptions.h"
#include "server/http/HeaderValues.h"
#include "server/jobs/ModelLimits.h"

#include "fmu/FmuExport.h"
#include "fmu/ModelInterface.h"

namespace tlmhub::server {

namespace {

// ?parameters=Comp.a,Comp.b&identifier=Name
fmu::InterfaceOptions interfaceOptions(const Call& call)
{
    fmu::InterfaceOptions options;
    if (const auto it = call.params.query.find("parameters"); it != call.params.query.end())
        options.parameters = commaSeparated(it->second);
    if (const auto it = call.params.query.find("identifier"); it != call.params.query.end())
        options.modelIdentifier = it->second;
    return options;
}

// A model without a valid interface (an unknown parameter path, a bad identifier, a model
// that does not load) is a well-formed request the model cannot satisfy: 422 with the
// core's code.
Response noInterface(const Status& status)
{
    const std::string at = status.path().empty() ? "" : " (at " + status.path() + ")";
    return apiError(http::status::unprocessable_entity, protocolErrorCode(status.code()), status.message() + at);
}

protocol::FmuPortVariable portVariable(const std::pair<std::string, std::string>& slot)
{
    return {.nodeVariable = slot.first, .variable = slot.second};
}

protocol::FmuInterface interfaceJson(const fmu::ModelDescription& d)
{
    protocol::FmuInterface out;
    out.modelIdentifier = d.modelIdentifier;
    out.modelName = d.modelName;
    out.defaultExperiment = {.startTime = d.startTime, .stopTime = d.stopTime, .stepSize = d.stepSize};
    for (const fmu::ScalarVariable& v : d.variables)
        out.variables.push_back({.name = v.name, .valueReference = v.valueReference,
                                 .causality = fmu::causalityName(v.causality),
                                 .variability = fmu::variabilityName(v.variability),
                                 .type = fmu::variableTypeName(v.type), .unit = v.unit,
                                 .description = v.description, .start = v.start});
    for (const fmu::PowerPort& p : d.powerPorts) {
        protocol::FmuPowerPort port;
        port.name = p.name;
        port.nodeType = p.nodeType;
        port.kind = std::string(1, p.kind);
        for (const auto& slot : p.inputs) port.inputs.push_back(portVariable(slot));
        for (const auto& slot : p.outputs) port.outputs.push_back(portVariable(slot));
        out.powerPorts.push_back(std::move(port));
    }
    return out;
}

// The interface of the stored model `hmf`, loaded within the server's model limits; on
// failure `error` holds the 422 saying why.
std::optional<fmu::ModelInterface> storedInterface(Services& s, const ModelSummary& model, const std::string& hmf,
                                                   const fmu::InterfaceOptions& options, Response& error)
{
    LoadedModel loaded = loadUntrustedModel(hmf, s.options.limits.model, "", model.name);
    if (const Status status = loaded.status(); !status) {
        error = noInterface(status);
        return std::nullopt;
    }
    auto described = fmu::describeInterface(*loaded.root, options);
    if (!described) {
        error = noInterface(described.status());
        return std::nullopt;
    }
    return std::move(*described);
}

Response getFmuInterface(Services& s, Call& call)
{
    const auto id = parseId(call.params.path["id"]);
    const auto summary = id ? readableModel(s, call.who(), *id) : std::nullopt;
    if (!summary) return apiError(http::status::not_found, "not_found", "no such model");
    Response error;
    const auto described = storedInterface(s, *summary, s.models.hmf(summary->id).value_or(""), interfaceOptions(call), error);
    if (!described) return error;
    return jsonResponse(http::status::ok, interfaceJson(described->description));
}

Response getFmu(Services& s, Call& call)
{
    const auto id = parseId(call.params.path["id"]);
    const auto summary = id ? readableModel(s, call.who(), *id) : std::nullopt;
    if (!summary) return apiError(http::status::not_found, "not_found", "no such model");
    // argv0 is only a fallback for a system without /proc/self/exe: none here.
    const auto runtime = fmu::findFmuRuntime("");
    if (!runtime)
        return apiError(http::status::service_unavailable, "unavailable",
                        "FMU export is not available on this server: " + runtime.status().message());
    const std::string hmf = s.models.hmf(summary->id).value_or("");
    const fmu::InterfaceOptions options = interfaceOptions(call);
    // Checked within the server's model limits first: the export loads the text as it is.
    Response error;
    const auto described = storedInterface(s, *summary, hmf, options, error);
    if (!described) return error;
    const auto zip = fmu::exportFmu(hmf, summary->name + ".hmf", options, *runtime);
    if (!zip && zip.status().code() == StatusCode::IoError)   // the runtime's files, not the model
        return apiError(http::status::internal_server_error, "internal", zip.status().message());
    if (!zip) return noInterface(zip.status());
    Response res = textResponse(http::status::ok, *zip, "application/zip");
    res.set(http::field::content_disposition,
            attachmentDisposition(described->description.modelIdentifier + ".fmu"));
    return res;
}

} // namespace

void addFmuRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/models/{id}/fmu/interface", true, getFmuInterface});
    // Zipping the model with the runtime library takes a moment of CPU per download: on the
    // checks pool, like the lab's model runs, so the request pool stays free.
    // Not on the lab's check pool: an export must not hold up students' pretests.
    routes.push_back({http::verb::get, "/models/{id}/fmu", true, getFmu, RouteWork::LargeReply});
}

} // namespace tlmhub::server
