#include "server/jobs/PreparedJob.h"

#include "server/api/CoreErrorCodes.h"
#include "server/jobs/ModelLimits.h"

#include "core/ParameterPath.h"
#include "core/ParameterTexts.h"
#include "core/hmf/HmfLoader.h"

#include <cmath>
#include <sstream>

namespace tlmhub::server {

namespace {

std::string describe(double v)
{
    std::ostringstream os;
    os << v;
    return os.str();
}

std::string sourceName(const JobRequest& request)
{
    return request.modelId ? "model " + std::to_string(*request.modelId) : "model";
}

// Applies the request to a model that is within the limits, and compiles it.
bool prepareLoaded(const JobRequest& request, Model model, const JobLimits& limits, PreparedJob& out,
                   PrepareError& error)
{
    System& root = model.root();
    if (const Status set = applyParameterOverrides(root, request.parameters); !set) {
        error = {protocolErrorCode(set.code()), set.message()};
        return false;
    }
    out.usedParameters = parameterTexts(root);

    const JobSettings& s = request.settings;
    if (request.settingsFixed) {
        const std::size_t ownLogSamples = root.requestedLogSamples ? root.requestedLogSamples : kDefaultLogSamples;
        const auto differs = [](const auto& asked, auto own) { return asked && *asked != own; };
        if (differs(s.start, root.startTime) || differs(s.stop, root.stopTime) ||
            differs(s.step, root.desiredTimestep) || differs(s.logSamples, ownLogSamples)) {
            error = {"locked", "an assignment's copy runs with its template's settings (start " +
                                   describe(root.startTime) + ", step " + describe(root.desiredTimestep) +
                                   ", stop " + describe(root.stopTime) + ", " + std::to_string(ownLogSamples) +
                                   " log samples)"};
            return false;
        }
    }
    out.start = s.start.value_or(root.startTime);
    out.stop = s.stop.value_or(root.stopTime);
    out.step = s.step.value_or(root.desiredTimestep);
    out.logSamples = s.logSamples.value_or(root.requestedLogSamples ? root.requestedLogSamples
                                                                    : kDefaultLogSamples);
    if (!std::isfinite(out.start) || !std::isfinite(out.stop) || !std::isfinite(out.step) ||
        !(out.step > 0.0) || !(out.stop >= out.start)) {
        error = {"bad_request", "need finite times with stop >= start and step > 0 (start " +
                                    describe(out.start) + ", step " + describe(out.step) + ", stop " +
                                    describe(out.stop) + ")"};
        return false;
    }
    const double steps = std::ceil((out.stop - out.start) / out.step);
    if (steps > static_cast<double>(limits.maxSteps)) {
        error = {"limit_exceeded", "the job needs " + describe(steps) + " steps; the limit is " +
                                       std::to_string(limits.maxSteps) + " (--max-steps)"};
        return false;
    }
    out.steps = static_cast<std::uint64_t>(steps);
    if (out.logSamples > limits.maxLogSamples) {
        error = {"limit_exceeded", "log_samples " + std::to_string(out.logSamples) + " is above the limit of " +
                                       std::to_string(limits.maxLogSamples) + " (--max-log-samples)"};
        return false;
    }
    Result<Simulation> compiled = compile(std::move(model), {out.start, out.stop, out.step, out.logSamples});
    if (!compiled) {
        error = {protocolErrorCode(compiled.status().code()), compiled.status().message()};
        return false;
    }
    out.simulation.emplace(std::move(*compiled));
    return true;
}

} // namespace

Status applyParameterOverrides(System& root, const std::map<std::string, std::string>& parameters)
{
    // System parameters first: component values may refer to them.
    for (const bool systemParameters : {true, false}) {
        for (const auto& [key, value] : parameters) {
            if ((key.find('.') == std::string::npos) != systemParameters) continue;
            if (Status set = setParameterValue(root, key, value); !set) return set;
        }
    }
    return {};
}

bool prepareJob(const JobRequest& request, const JobLimits& limits, PreparedJob& out, PrepareError& error)
{
    if (request.hmf.empty()) {
        error = {"invalid_model", "the job has no model"};
        return false;
    }
    LoadedModel loaded = loadUntrustedModel(request.hmf, limits.model, request.modelDirectory, sourceName(request));
    if (const Status status = loaded.status(); !status) {
        error = {protocolErrorCode(status.code()), status.message()};
        return false;
    }
    return prepareLoaded(request, Model(std::move(loaded.root)), limits, out, error);
}

bool prepareJob(const JobRequest& request, Model model, const JobLimits& limits, PreparedJob& out,
                PrepareError& error)
{
    if (std::string problem = modelLimitProblem(model.root(), request.hmf.size(), limits.model, sourceName(request));
        !problem.empty()) {
        error = {protocolErrorCode(StatusCode::InvalidModel), std::move(problem)};
        return false;
    }
    // Relative paths resolve as they will when the stored request is compiled again.
    model.root().modelDirectory = request.modelDirectory;
    return prepareLoaded(request, std::move(model), limits, out, error);
}

} // namespace tlmhub::server
