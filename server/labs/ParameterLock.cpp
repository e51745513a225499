#include "server/labs/ParameterLock.h"
#include "server/NumberText.h"

#include "core/Model.h"
#include "core/ParameterPath.h"
#include "core/Parameter.h"
#include "core/hmf/HmfLoader.h"

#include <charconv>
#include <cmath>

namespace tlmhub::server {

namespace {

std::optional<double> plainNumber(const std::string& text)
{
    double value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::string boundsText(const AllowedParameter& p)
{
    const auto bound = [](std::optional<double> value, const char* none) {
        return value ? numberText(*value) : std::string(none);
    };
    return "[" + bound(p.min, "-inf") + ", " + bound(p.max, "inf") + "]";
}

} // namespace

std::optional<ParameterLock> ParameterLock::parse(const nlohmann::json& list, std::string& error)
{
    if (!list.is_array()) {
        error = "parameters: must be a list";
        return std::nullopt;
    }
    ParameterLock lock;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const nlohmann::json& entry = list[i];
        const std::string where = "parameters[" + std::to_string(i) + "]";
        if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string() ||
            entry["name"].get<std::string>().empty()) {
            error = where + ": needs a name";
            return std::nullopt;
        }
        AllowedParameter p{entry["name"].get<std::string>(), std::nullopt, std::nullopt};
        for (const auto& [key, value] : entry.items()) {
            if (key == "name") continue;
            if ((key != "min" && key != "max") || !value.is_number()) {
                error = where + "." + key + ": only name, min and max (numbers) are allowed";
                return std::nullopt;
            }
            (key == "min" ? p.min : p.max) = value.get<double>();
        }
        if (p.min && p.max && *p.min > *p.max) {
            error = where + ": min is above max";
            return std::nullopt;
        }
        if (lock.find(p.name)) {
            error = where + ": " + p.name + " is listed twice";
            return std::nullopt;
        }
        lock.mParameters.push_back(std::move(p));
    }
    return lock;
}

nlohmann::json ParameterLock::toJson() const
{
    nlohmann::json list = nlohmann::json::array();
    for (const AllowedParameter& p : mParameters) {
        nlohmann::json entry = {{"name", p.name}};
        if (p.min) entry["min"] = *p.min;
        if (p.max) entry["max"] = *p.max;
        list.push_back(std::move(entry));
    }
    return list;
}

namespace {

// "GainP.k#Value" (an input's start value as the editor names it) is "GainP.k" (as a job names it).
std::string_view canonicalName(std::string_view name)
{
    constexpr std::string_view kStartValue = "#Value";
    if (name.size() > kStartValue.size() && name.substr(name.size() - kStartValue.size()) == kStartValue)
        name.remove_suffix(kStartValue.size());
    return name;
}

} // namespace

const AllowedParameter* ParameterLock::find(const std::string& name) const
{
    for (const AllowedParameter& p : mParameters)
        if (canonicalName(p.name) == canonicalName(name)) return &p;
    return nullptr;
}

std::string ParameterLock::numberProblem(const std::string& name, double value) const
{
    const AllowedParameter* p = find(name);
    if (!p) return name + " is not one of the parameters this assignment lets you change";
    if (!std::isfinite(value) || (p->min && value < *p->min) || (p->max && value > *p->max))
        return name + " must stay within " + boundsText(*p);
    return "";
}

std::string ParameterLock::valueProblem(const std::string& name, const std::string& value) const
{
    const AllowedParameter* p = find(name);
    if (!p) return name + " is not one of the parameters this assignment lets you change";
    if (!p->min && !p->max) return "";
    const auto number = plainNumber(value);
    if (!number) return name + " takes a number within " + boundsText(*p) + " here, not '" + value + "'";
    return numberProblem(name, *number);
}

std::string ParameterLock::changeProblem(const std::string& base, const std::string& changed,
                                         const ModelLimits& limits) const
{
    LoadedModel before = loadUntrustedModel(base, limits, "", "the copy");
    LoadedModel after = loadUntrustedModel(changed, limits, "", "the new text");
    if (!before.root) return "the copy does not load: " + before.firstError();
    if (!after.root) return "the new text does not load: " + after.firstError();
    // Carry the listed parameters' new values over to the copy as it was: if the two models
    // then serialise alike, nothing else changed.
    for (const AllowedParameter& p : mParameters) {
        const Result<ParameterRef> found = findParameter(*after.root, p.name);
        if (!found) return "the new text lacks " + p.name;
        const std::string value = found->parameter->value;
        if (const std::string problem = valueProblem(p.name, value); !problem.empty()) return problem;
        if (const Status set = setParameterValue(*before.root, p.name, value); !set)
            return p.name + ": " + set.message();
    }
    if (Model(std::move(before.root)).toHmf() != Model(std::move(after.root)).toHmf())
        return "only the listed parameters may change in this assignment (the new text changes more)";
    return "";
}

std::string parameterPath(const std::vector<std::string>& system, const std::string& component,
                          const std::string& parameter)
{
    std::string path;
    if (component.empty()) {
        // A system parameter: "name" of the root, "Sub.name" of a subsystem ("A$Sub.name" deeper).
        if (system.empty()) return parameter;
        for (std::size_t i = 0; i + 1 < system.size(); ++i) path += system[i] + "$";
        return path + system.back() + "." + parameter;
    }
    for (const std::string& name : system) path += name + "$";
    return path + component + "." + parameter;
}

} // namespace tlmhub::server
