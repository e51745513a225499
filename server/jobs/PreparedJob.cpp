#include "server/jobs/PreparedJob.h"

#include "server/api/CoreErrorCodes.h"

#include "core/ParameterPath.h"
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

} // namespace

bool prepareJob(const JobRequest& request, const JobLimits& limits, PreparedJob& out, PrepareError& error)
{
    if (request.hmf.empty()) {
        error = {"invalid_model", "the job has no model"};
        return false;
    }
    const std::string source = request.modelId ? "model " + std::to_string(*request.modelId) : "model";
    LoadedModel loaded = loadUntrustedModel(request.hmf, limits.model, request.modelDirectory, source);
    if (const Status status = loaded.status(); !status) {
        error = {protocolErrorCode(status.code()), status.message()};
        return false;
    }
    System& root = *loaded.root;

    // System parameters first: component values may refer to them.
    for (int pass = 0; pass < 2; ++pass) {
        for (const auto& [key, value] : request.parameters) {
            const bool isSystemParameter = key.find('.') == std::string::npos;
            if (isSystemParameter != (pass == 0)) continue;
            if (const Status set = setParameterValue(root, key, value); !set) {
                error = {protocolErrorCode(set.code()), set.message()};
                return false;
            }
        }
    }

    const JobSettings& s = request.settings;
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
                                       std::to_string(limits.maxSteps)};
        return false;
    }
    out.steps = static_cast<std::uint64_t>(steps);
    if (out.logSamples > limits.maxLogSamples) {
        error = {"limit_exceeded", "log_samples " + std::to_string(out.logSamples) +
                                       " is above the limit of " + std::to_string(limits.maxLogSamples)};
        return false;
    }
    Result<Simulation> compiled = compile(std::move(loaded.root), {out.start, out.stop, out.step, out.logSamples});
    if (!compiled) {
        error = {protocolErrorCode(compiled.status().code()), compiled.status().message()};
        return false;
    }
    out.simulation.emplace(std::move(*compiled));
    return true;
}

} // namespace tlmhub::server
