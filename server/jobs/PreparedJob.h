#pragma once
// Turning a JobRequest into a compiled simulation: load the .hmf (or take the model from
// memory), apply the parameter overrides, resolve the settings, check the limits and compile.
// Done once, at submission; the queue keeps the compiled job for its worker. Only a job
// queued before a restart (the store keeps its request, not the compiled model) is prepared
// again by the runner.
#include "core/Model.h"
#include "core/Simulation.h"
#include "server/jobs/Job.h"

#include <map>
#include <optional>
#include <string>

namespace tlmhub::server {

struct PreparedJob {
    std::optional<Simulation> simulation;         // owns the loaded model
    double start = 0.0, step = 0.0, stop = 0.0;   // s
    std::size_t logSamples = 0;
    std::uint64_t steps = 0;                      // ceil((stop - start) / step)
    // Every parameter's value text with the overrides applied (JobRequest::usedParameters).
    std::map<std::string, std::string> usedParameters;
};

struct PrepareError {
    std::string code;      // a protocol error code: invalid_model, unknown_component_type, invalid_parameter, ...
    std::string message;
};

// Log samples of a job whose model and request both leave them at 0.
constexpr std::size_t kDefaultLogSamples = 1024;

// A job's parameter overrides ("Comp.Param", "Sub$Comp.Param", or a system parameter's name),
// system parameters first since component values may refer to them.
Status applyParameterOverrides(System& root, const std::map<std::string, std::string>& parameters);

bool prepareJob(const JobRequest& request, const JobLimits& limits, PreparedJob& out,
                PrepareError& error);
// The same for a model in memory (an editor's copy) whose text request.hmf already holds:
// nothing is parsed.
bool prepareJob(const JobRequest& request, Model model, const JobLimits& limits, PreparedJob& out,
                PrepareError& error);

} // namespace tlmhub::server
