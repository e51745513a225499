#include "cli/remote/StudyRequest.h"

#include <algorithm>
#include <cmath>

namespace tlmhub::cli::remote {

namespace {

std::vector<std::string> split(const std::string& text, char separator)
{
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (std::size_t at; (at = text.find(separator, from)) != std::string::npos; from = at + 1)
        parts.push_back(text.substr(from, at - from));
    parts.push_back(text.substr(from));
    return parts;
}

// "NAME=VALUE" of option `option`.
std::pair<std::string, std::string> assignment(const std::string& option, const std::string& text,
                                               const char* form)
{
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
        throw UsageError("--" + option + " needs " + form + ", got '" + text + "'");
    return {text.substr(0, equals), text.substr(equals + 1)};
}

double number(const std::string& option, const std::string& text, const std::string& whole)
{
    const std::optional<double> value = parseNumber(text);
    if (!value || !std::isfinite(*value))
        throw UsageError("--" + option + ": '" + text + "' is not a number in '" + whole + "'");
    return *value;
}

nlohmann::json numberOrText(const std::string& text)
{
    const std::optional<double> value = parseNumber(text);
    return value ? nlohmann::json(*value) : nlohmann::json(text);
}

// A random sweep samples `from:to` (its steps are not needed).
nlohmann::json sweepValues(const std::string& text, const std::string& whole, bool random)
{
    if (text.find(':') != std::string::npos) {
        const std::vector<std::string> range = split(text, ':');
        if (random && range.size() == 2)
            return {{"from", number("vary", range[0], whole)}, {"to", number("vary", range[1], whole)}};
        const std::optional<double> steps = range.size() == 3 ? parseNumber(range[2]) : std::nullopt;
        if (!steps || *steps < 1 || *steps != std::floor(*steps))
            throw UsageError("--vary needs Comp.P=from:to:steps with a whole number of steps, got '" + whole + "'");
        return {{"from", number("vary", range[0], whole)}, {"to", number("vary", range[1], whole)},
                {"steps", static_cast<long long>(*steps)}};
    }
    nlohmann::json values = nlohmann::json::array();
    for (const std::string& value : split(text, ',')) values.push_back(number("vary", value, whole));
    return values;
}

nlohmann::json outputs(const Arguments& args)
{
    static const std::vector<std::string> known = {"final", "min", "max", "mean"};
    nlohmann::json variables = nlohmann::json::array(), values = nlohmann::json::array();
    for (const std::string& output : args.values("output")) {
        const std::size_t colon = output.rfind(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == output.size())
            throw UsageError("--output needs VARIABLE:final,max,..., got '" + output + "'");
        const std::string variable = output.substr(0, colon);
        if (std::find(variables.begin(), variables.end(), variable) == variables.end()) variables.push_back(variable);
        for (const std::string& value : split(output.substr(colon + 1), ',')) {
            if (std::find(known.begin(), known.end(), value) == known.end())
                throw UsageError("--output: '" + value + "' is not one of final, min, max, mean in '" + output + "'");
            if (std::find(values.begin(), values.end(), value) == values.end()) values.push_back(value);
        }
    }
    nlohmann::json out = nlohmann::json::object();
    if (!variables.empty()) out["variables"] = variables;
    if (!values.empty()) out["values"] = values;
    if (args.has("full")) out["full"] = true;
    return out;
}

nlohmann::json objectiveTerm(const std::string& text)
{
    static const std::vector<std::string> functions = {"final", "min", "max", "mean", "overshoot", "ise"};
    const std::string usage = "--objective needs FUNCTION:VARIABLE[:REFERENCE_VARIABLE][*WEIGHT], got '" + text + "'";
    std::string term = text;
    nlohmann::json weight;
    if (const std::size_t star = term.rfind('*'); star != std::string::npos) {
        weight = number("objective", term.substr(star + 1), text);
        term.erase(star);
    }
    const std::vector<std::string> parts = split(term, ':');
    if (parts.size() < 2 || parts.size() > 3 || parts[1].empty()) throw UsageError(usage);
    const std::string& function = parts[0];
    if (std::find(functions.begin(), functions.end(), function) == functions.end())
        throw UsageError("--objective: '" + function + "' is not one of final, min, max, mean, overshoot, ise");
    if ((function == "ise") != (parts.size() == 3))
        throw UsageError("--objective: ise needs a reference variable (ise:VARIABLE:REFERENCE), the others "
                         "none; got '" + text + "'");
    nlohmann::json out = {{"function", function}, {"variable", parts[1]}};
    if (parts.size() == 3) out["reference_variable"] = parts[2];
    if (!weight.is_null()) out["weight"] = weight;
    return out;
}

long long wholeNumber(const Arguments& args, const std::string& option, double least)
{
    const double value = args.number(option).value_or(NAN);
    if (!(value >= least) || value != std::floor(value) || value > 1e15)
        throw UsageError("--" + option + " needs a whole number" + (least > 0 ? " of at least 1" : "") + ", got '" +
                         args.value(option) + "'");
    return static_cast<long long>(value);
}

// What every study takes as a job does: fixed parameters and the simulation times.
void addRunSettings(nlohmann::json& request, const Arguments& args)
{
    if (!args.values("param").empty()) request["parameters"] = parameterValues(args.values("param"));
    for (const char* setting : {"start", "step", "stop"}) {
        if (!args.has(setting)) continue;
        const std::optional<double> value = args.number(setting);
        if (!value || !std::isfinite(*value))
            throw UsageError(std::string("--") + setting + " needs a number, got '" + args.value(setting) + "'");
        request[setting] = *value;
    }
}

} // namespace

nlohmann::json parameterValues(const std::vector<std::string>& assignments)
{
    nlohmann::json parameters = nlohmann::json::object();
    for (const std::string& text : assignments) {
        const auto [name, value] = assignment("param", text, "Comp.P=value");
        parameters[name] = numberOrText(value);
    }
    return parameters;
}

nlohmann::json sweepRequest(const std::string& name, const Arguments& args)
{
    if (args.values("vary").empty()) throw UsageError("sweep needs at least one --vary");
    const std::string mode = args.has("mode") ? args.value("mode") : "grid";
    if (mode != "grid" && mode != "list" && mode != "random")
        throw UsageError("--mode is grid, list or random, got '" + mode + "'");
    const bool random = mode == "random";
    if (random != args.has("samples")) throw UsageError("--samples N goes with --mode random, and only with it");
    if (args.has("seed") && !random) throw UsageError("--seed goes with --mode random (or optimise)");
    nlohmann::json parameters = nlohmann::json::object();
    for (const std::string& vary : args.values("vary")) {
        const auto [parameter, values] = assignment("vary", vary, "Comp.P=from:to:steps or Comp.P=v1,v2,...");
        if (parameters.contains(parameter)) throw UsageError("--vary: " + parameter + " is varied twice");
        parameters[parameter] = sweepValues(values, vary, random);
    }
    nlohmann::json request = {{"kind", "sweep"}, {"name", name}};
    addRunSettings(request, args);
    if (nlohmann::json out = outputs(args); !out.empty()) request["outputs"] = out;
    request["sweep"] = {{"mode", mode}, {"parameters", parameters}};
    if (random) request["sweep"]["samples"] = wholeNumber(args, "samples", 1);
    if (args.has("seed")) request["sweep"]["seed"] = wholeNumber(args, "seed", 0);
    return request;
}

nlohmann::json sensitivityRequest(const std::string& name, const Arguments& args)
{
    if (args.values("distribution").empty()) throw UsageError("sensitivity needs at least one --distribution");
    if (args.values("output").empty()) throw UsageError("sensitivity needs at least one --output");
    if (!args.has("runs")) throw UsageError("sensitivity needs --runs N");
    nlohmann::json parameters = nlohmann::json::object();
    for (const std::string& text : args.values("distribution")) {
        const char* form = "Comp.P=normal:MEAN:SD or Comp.P=uniform:MIN:MAX";
        const auto [parameter, spec] = assignment("distribution", text, form);
        const std::vector<std::string> parts = split(spec, ':');
        if (parts.size() != 3 || (parts[0] != "normal" && parts[0] != "uniform"))
            throw UsageError(std::string("--distribution needs ") + form + ", got '" + text + "'");
        if (parameters.contains(parameter)) throw UsageError("--distribution: " + parameter + " is given twice");
        const double a = number("distribution", parts[1], text), b = number("distribution", parts[2], text);
        parameters[parameter] = parts[0] == "normal" ? nlohmann::json{{"distribution", "normal"}, {"mean", a}, {"sd", b}}
                                                     : nlohmann::json{{"distribution", "uniform"}, {"min", a}, {"max", b}};
    }
    nlohmann::json request = {{"kind", "sensitivity"}, {"name", name}};
    addRunSettings(request, args);
    request["outputs"] = outputs(args);
    request["sensitivity"] = {{"runs", wholeNumber(args, "runs", 1)}, {"parameters", parameters}};
    if (args.has("seed")) request["sensitivity"]["seed"] = wholeNumber(args, "seed", 0);
    return request;
}

nlohmann::json optimiseRequest(const std::string& name, const Arguments& args)
{
    if (args.values("bound").empty()) throw UsageError("optimise needs at least one --bound");
    if (args.values("objective").empty()) throw UsageError("optimise needs at least one --objective");
    const std::string algorithm = args.has("algorithm") ? args.value("algorithm") : "complex-rf";
    if (algorithm != "complex-rf" && algorithm != "nelder-mead" && algorithm != "particle-swarm")
        throw UsageError("--algorithm is complex-rf, nelder-mead or particle-swarm, got '" + algorithm + "'");
    nlohmann::json parameters = nlohmann::json::object();
    for (const std::string& bound : args.values("bound")) {
        const auto [parameter, range] = assignment("bound", bound, "Comp.P=min:max");
        const std::vector<std::string> limits = split(range, ':');
        if (limits.size() != 2) throw UsageError("--bound needs Comp.P=min:max, got '" + bound + "'");
        const double min = number("bound", limits[0], bound), max = number("bound", limits[1], bound);
        if (!(min < max)) throw UsageError("--bound needs min < max, got '" + bound + "'");
        if (parameters.contains(parameter)) throw UsageError("--bound: " + parameter + " is bounded twice");
        parameters[parameter] = {{"min", min}, {"max", max}};
    }
    nlohmann::json terms = nlohmann::json::array();
    for (const std::string& objective : args.values("objective")) terms.push_back(objectiveTerm(objective));
    const char* goal = args.has("maximise") ? "maximise" : "minimise";
    nlohmann::json optimise = {{"algorithm", algorithm},
                               {"parameters", parameters},
                               {"objective", {{"goal", goal}, {"terms", terms}}}};
    if (args.has("max-evaluations")) optimise["max_evaluations"] = wholeNumber(args, "max-evaluations", 1);
    if (args.has("seed")) optimise["seed"] = wholeNumber(args, "seed", 0);
    if (args.has("tolerance")) {
        const std::optional<double> tolerance = args.number("tolerance");
        if (!tolerance || !(*tolerance > 0) || !std::isfinite(*tolerance))
            throw UsageError("--tolerance needs a positive number, got '" + args.value("tolerance") + "'");
        optimise["tolerance"] = *tolerance;
    }
    nlohmann::json request = {{"kind", "optimise"}, {"name", name}, {"optimise", optimise}};
    addRunSettings(request, args);
    return request;
}

} // namespace tlmhub::cli::remote
