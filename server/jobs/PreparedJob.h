#pragma once
// Turning a JobRequest into a model ready to initialize: load the .hmf, apply the parameter
// overrides, resolve the settings and check the limits. Done once at submit (to refuse a bad
// job with a precise error) and again by the runner (queued jobs keep only their request).
#include "core/System.h"
#include "server/jobs/Job.h"

#include <memory>
#include <string>

namespace tlmhub::server {

struct PreparedJob {
    std::unique_ptr<System> root;
    double start = 0.0, step = 0.0, stop = 0.0;   // s
    std::size_t logSamples = 0;
    std::uint64_t steps = 0;                      // ceil((stop - start) / step)
};

struct PrepareError {
    std::string code;      // a protocol error code: invalid_model, unknown_component_type, invalid_parameter, ...
    std::string message;
};

// Log samples of a job whose model and request both leave them at 0.
constexpr std::size_t kDefaultLogSamples = 1024;

bool prepareJob(const JobRequest& request, const JobLimits& limits, PreparedJob& out,
                PrepareError& error);

// Set one parameter: "Comp.Param" (component at the root), "Sub$Comp.Param" (nested), or a
// bare system parameter name of the root. "Comp.x" also finds the input variable "x#Value".
// The value must evaluate; otherwise the old value is kept and `error` says why.
bool applyParameter(System& root, const std::string& key, const std::string& value,
                    std::string& error);

} // namespace tlmhub::server
