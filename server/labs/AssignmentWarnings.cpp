#include "server/labs/AssignmentWarnings.h"

#include "server/labs/LabChecks.h"
#include "server/NumberText.h"

#include "core/Component.h"
#include "core/Parameter.h"
#include "core/ParameterEvaluator.h"
#include "core/ParameterPath.h"
#include "core/System.h"

namespace tlmhub::server {

namespace {

// "between 0 and 0.1", "at least 0" or "at most 0.1".
std::string warningBounds(const AllowedParameter& p)
{
    if (p.min && p.max) return "between " + numberText(*p.min) + " and " + numberText(*p.max);
    if (p.min) return "at least " + numberText(*p.min);
    return "at most " + numberText(*p.max);
}

} // namespace

std::vector<AssignmentWarning> parameterWarnings(const ParameterLock& lock, const std::string& hmf,
                                                 const std::string& role, const ModelLimits& limits)
{
    std::vector<AssignmentWarning> warnings;
    if (lock.parameters().empty()) return warnings;
    LoadedModel model = loadUntrustedModel(hmf, limits, "", "the " + role);
    // A model that does not load was refused when it was stored; nothing to say about it here.
    if (!model.root) return warnings;
    const std::string article = role == "template" ? "The template" : "The solution";
    for (const AllowedParameter& p : lock.parameters()) {
        const Result<ParameterRef> found = findParameter(*model.root, p.name);
        if (!found) {
            warnings.push_back({role + "_lacks_parameter",
                                article + " has no parameter " + p.name + ", so students cannot change it."});
            continue;
        }
        if (!p.min && !p.max) continue;
        // Evaluated as the run would, so a value that names a system parameter counts by its number.
        const Result<double> value = ParameterEvaluator::evaluateExpression(*found->owner, found->parameter->value);
        if (!value) continue;
        if ((p.min && *value < *p.min) || (p.max && *value > *p.max))
            warnings.push_back({role + "_outside_bounds",
                                article + " sets " + p.name + " to " + numberText(*value) +
                                    ", outside the bounds you set (" + warningBounds(p) + ")."});
    }
    return warnings;
}

std::vector<AssignmentWarning> solutionCheckWarnings(const std::vector<AssignmentCheck>& checks,
                                                     const ResultTable& reference)
{
    std::vector<AssignmentWarning> warnings;
    for (const CheckOutcome& outcome : evaluateChecks(checks, reference, &reference, false))
        if (!outcome.passed)
            warnings.push_back({"solution_fails_check",
                                "The solution fails the check \"" + outcome.name + "\": " + outcome.message + "."});
    return warnings;
}

nlohmann::json warningsJson(const std::vector<AssignmentWarning>& warnings)
{
    nlohmann::json list = nlohmann::json::array();
    for (const AssignmentWarning& w : warnings) list.push_back({{"code", w.code}, {"message", w.message}});
    return list;
}

} // namespace tlmhub::server
