#pragma once
// What a student may change in a copy of an assignment whose edit mode is "parameters": the
// listed parameters (by path, core/ParameterPath.h), each within optional bounds. One rule,
// asked by every path that changes or runs a copy: WebSocket edits, PUT /models/{id}, a
// job's parameter overrides and a study's varied parameters.
#include "server/jobs/ModelLimits.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct AllowedParameter {
    std::string name;                    // "Comp.param", "Sub$Comp.param" or a system parameter
    std::optional<double> min, max;
};

class ParameterLock {
public:
    // From an assignment's list ([{"name", "min"?, "max"?}]); nullopt with `error` naming
    // the entry that is wrong.
    static std::optional<ParameterLock> parse(const nlohmann::json& list, std::string& error);
    nlohmann::json toJson() const;
    const std::vector<AllowedParameter>& parameters() const { return mParameters; }
    // The listed parameter `name` names (an input's start value "Comp.x#Value" and "Comp.x"
    // alike), or null.
    const AllowedParameter* find(const std::string& name) const;

    // "" when `value` may be given to parameter `name`, else why not. A bounded parameter
    // takes plain numbers only.
    std::string valueProblem(const std::string& name, const std::string& value) const;
    std::string numberProblem(const std::string& name, double value) const;
    // "" when `changed` differs from `base` (both .hmf texts) only in listed parameters
    // within their bounds, else the first difference that is not allowed.
    std::string changeProblem(const std::string& base, const std::string& changed, const ModelLimits& limits) const;

private:
    std::vector<AllowedParameter> mParameters;
};

// The path (core/ParameterPath.h) a WebSocket parameter.set names (`component` set) or a
// sysparam.set names (`component` empty), given the request's system path.
std::string parameterPath(const std::vector<std::string>& system, const std::string& component,
                          const std::string& parameter);

} // namespace tlmhub::server
