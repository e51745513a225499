#pragma once
// What a teacher is warned of about their own assignment, so that students are not handed
// an impossible task: the template or the solution holds an allowed parameter at a value
// outside the bounds the teacher set (or lacks it), or the solution's own reference run fails
// one of the checks. Warnings never refuse a change: the teacher may be half-way through.
#include "server/jobs/ModelLimits.h"
#include "server/labs/ParameterLock.h"
#include "server/store/LabStore.h"

#include "core/ResultTable.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tlmhub::server {

struct AssignmentWarning {
    // template_outside_bounds, solution_outside_bounds, template_lacks_parameter,
    // solution_lacks_parameter or solution_fails_check (protocol: AssignmentWarning)
    std::string code;
    std::string message;   // a sentence for the teacher
};

// The listed parameters of `lock` in `hmf`, the model named by `role` ("template" or
// "solution"): each must exist, and a bounded one must evaluate to a number within its bounds.
std::vector<AssignmentWarning> parameterWarnings(const ParameterLock& lock, const std::string& hmf,
                                                 const std::string& role, const ModelLimits& limits);
// The checks that the solution's reference run does not pass.
std::vector<AssignmentWarning> solutionCheckWarnings(const std::vector<AssignmentCheck>& checks,
                                                     const ResultTable& reference);

nlohmann::json warningsJson(const std::vector<AssignmentWarning>& warnings);

} // namespace tlmhub::server
