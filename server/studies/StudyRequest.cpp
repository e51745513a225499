#include "server/studies/StudyRequest.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace tlmhub::server {

namespace {

using Json = nlohmann::json;

// Bounds on what one request may list (the run count has its own, configurable limit).
constexpr std::size_t kMaxParameters = 64;
constexpr std::size_t kMaxListValues = 100'000;
constexpr std::size_t kMaxOutputVariables = 64;
constexpr std::size_t kMaxObjectiveTerms = 32;
constexpr std::size_t kMaxReferencePoints = 1'000'000;

// Reads the request part by part; the first problem found is kept.
class Reader {
public:
    std::string error;

    bool fail(const std::string& message)
    {
        if (error.empty()) error = message;
        return false;
    }
    bool number(const Json& j, const std::string& what, double& out)
    {
        if (!j.is_number()) return fail(what + " must be a number");
        out = j.get<double>();
        if (!std::isfinite(out)) return fail(what + " must be finite");
        return true;
    }
    bool count(const Json& j, const std::string& what, std::size_t& out, std::size_t max)
    {
        if (!j.is_number_integer() && !j.is_number_unsigned()) return fail(what + " must be a whole number");
        if (j.is_number_integer() && j.get<std::int64_t>() < 0) return fail(what + " must not be negative");
        const auto value = j.get<std::uint64_t>();
        if (value > max) return fail(what + " is " + std::to_string(value) + ", at most " + std::to_string(max));
        out = static_cast<std::size_t>(value);
        return true;
    }
    bool text(const Json& j, const std::string& what, std::string& out)
    {
        if (!j.is_string()) return fail(what + " must be a string");
        out = j.get<std::string>();
        return true;
    }
    bool object(const Json& j, const std::string& what)
    {
        return j.is_object() || fail(what + " must be an object");
    }
    bool parameterName(const std::string& name, const std::string& what)
    {
        if (name.empty() || name.size() > 512) return fail(what + ": a parameter name must have 1 to 512 characters");
        return true;
    }
    bool seed(const Json& parent, std::uint64_t& out)
    {
        if (!parent.contains("seed")) return true;
        const Json& j = parent["seed"];
        if (!j.is_number_unsigned() && !(j.is_number_integer() && j.get<std::int64_t>() >= 0))
            return fail("seed must be a whole number >= 0");
        out = j.get<std::uint64_t>();
        return true;
    }
};

bool readSettings(Reader& r, const Json& body, JobSettings& settings)
{
    const std::pair<const char*, std::optional<double>*> times[] = {
        {"start", &settings.start}, {"step", &settings.step}, {"stop", &settings.stop}};
    for (const auto& [key, field] : times) {
        if (!body.contains(key) || body[key].is_null()) continue;
        double value = 0;
        if (!r.number(body[key], key, value)) return false;
        *field = value;
    }
    if (body.contains("log_samples") && !body["log_samples"].is_null()) {
        std::size_t samples = 0;
        if (!r.count(body["log_samples"], "log_samples", samples, std::numeric_limits<std::uint32_t>::max())) return false;
        settings.logSamples = samples;
    }
    return true;
}

bool readFixedParameters(Reader& r, const Json& body, std::map<std::string, std::string>& out)
{
    if (!body.contains("parameters")) return true;
    const Json& parameters = body["parameters"];
    if (!r.object(parameters, "parameters")) return false;
    if (parameters.size() > 10'000) return r.fail("parameters: at most 10000");
    for (const auto& [name, value] : parameters.items()) {
        if (!r.parameterName(name, "parameters")) return false;
        if (value.is_string()) out[name] = value.get<std::string>();
        else if (value.is_number()) out[name] = value.dump();
        else return r.fail("parameters: '" + name + "' must be a string or a number");
    }
    return true;
}

bool readStatistic(Reader& r, const std::string& name, RunStatistic& out)
{
    for (RunStatistic s : {RunStatistic::Final, RunStatistic::Min, RunStatistic::Max, RunStatistic::Mean}) {
        if (name == runStatisticName(s)) {
            out = s;
            return true;
        }
    }
    return r.fail("outputs.values: '" + name + "' is not one of final, min, max, mean");
}

bool readOutputs(Reader& r, const Json& body, StudyOutputs& out)
{
    if (!body.contains("outputs")) return true;
    const Json& outputs = body["outputs"];
    if (!r.object(outputs, "outputs")) return false;
    if (outputs.contains("variables")) {
        const Json& variables = outputs["variables"];
        if (!variables.is_array()) return r.fail("outputs.variables must be a list of variable names");
        if (variables.size() > kMaxOutputVariables)
            return r.fail("outputs.variables: at most " + std::to_string(kMaxOutputVariables));
        for (const Json& v : variables) {
            std::string name;
            if (!r.text(v, "outputs.variables[]", name)) return false;
            out.variables.push_back(name);
        }
    }
    if (outputs.contains("values")) {
        const Json& values = outputs["values"];
        if (!values.is_array() || values.size() > 4) return r.fail("outputs.values must be a list of final, min, max, mean");
        for (const Json& v : values) {
            std::string name;
            RunStatistic statistic{};
            if (!r.text(v, "outputs.values[]", name) || !readStatistic(r, name, statistic)) return false;
            out.statistics.push_back(statistic);
        }
    } else if (!out.variables.empty()) {
        out.statistics = {RunStatistic::Final};
    }
    if (outputs.contains("full")) {
        if (!outputs["full"].is_boolean()) return r.fail("outputs.full must be true or false");
        out.full = outputs["full"].get<bool>();
    }
    return true;
}

bool readAxis(Reader& r, const std::string& name, const Json& spec, SweepAxis& axis)
{
    axis.name = name;
    const std::string what = "sweep.parameters." + name;
    if (spec.is_array()) {
        if (spec.empty() || spec.size() > kMaxListValues)
            return r.fail(what + ": a list needs 1 to " + std::to_string(kMaxListValues) + " values");
        std::vector<double> values;
        for (const Json& v : spec) {
            double value = 0;
            if (!r.number(v, what + "[]", value)) return false;
            values.push_back(value);
        }
        axis.values = std::move(values);
        return true;
    }
    if (!spec.is_object() || !spec.contains("from") || !spec.contains("to"))
        return r.fail(what + " must be a list of values or {from, to, steps}");
    SweepRange range;
    if (!r.number(spec["from"], what + ".from", range.from) || !r.number(spec["to"], what + ".to", range.to))
        return false;
    range.steps = 2;
    if (spec.contains("steps") && !r.count(spec["steps"], what + ".steps", range.steps, kMaxListValues)) return false;
    if (range.steps == 0) return r.fail(what + ".steps must be at least 1");
    axis.values = range;
    return true;
}

bool readSweep(Reader& r, const Json& body, StudyRequest& out)
{
    if (!body.contains("sweep")) return r.fail("a sweep needs \"sweep\": {parameters, mode}");
    const Json& sweep = body["sweep"];
    if (!r.object(sweep, "sweep")) return false;
    std::string mode = "grid";
    if (sweep.contains("mode") && !r.text(sweep["mode"], "sweep.mode", mode)) return false;
    if (mode == "grid") out.mode = SweepMode::Grid;
    else if (mode == "list") out.mode = SweepMode::List;
    else if (mode == "random") out.mode = SweepMode::Random;
    else return r.fail("sweep.mode '" + mode + "' is not one of grid, list, random");
    if (!sweep.contains("parameters") || !r.object(sweep["parameters"], "sweep.parameters"))
        return r.fail("sweep.parameters must name the swept parameters");
    if (sweep["parameters"].empty() || sweep["parameters"].size() > kMaxParameters)
        return r.fail("sweep.parameters: 1 to " + std::to_string(kMaxParameters) + " parameters");
    for (const auto& [name, spec] : sweep["parameters"].items()) {
        SweepAxis axis;
        if (!r.parameterName(name, "sweep.parameters") || !readAxis(r, name, spec, axis)) return false;
        out.axes.push_back(std::move(axis));
    }
    if (out.mode == SweepMode::Random) {
        if (!sweep.contains("samples")) return r.fail("a random sweep needs sweep.samples");
        if (!r.count(sweep["samples"], "sweep.samples", out.samples, std::numeric_limits<std::uint32_t>::max()))
            return false;
        if (!r.seed(sweep, out.seed)) return false;
    }
    if (sweepSize(out.axes, out.mode, out.samples) == 0)
        return r.fail(out.mode == SweepMode::List ? "sweep.mode list needs lists of equal length"
                                                  : "the sweep has no runs");
    return true;
}

bool readDistribution(Reader& r, const std::string& name, const Json& spec, RandomParameter& out)
{
    out.name = name;
    const std::string what = "sensitivity.parameters." + name;
    if (!r.object(spec, what)) return false;
    std::string kind;
    if (!spec.contains("distribution") || !r.text(spec["distribution"], what + ".distribution", kind)) return false;
    if (kind == "normal") {
        out.distribution.kind = Distribution::Kind::Normal;
        if (!spec.contains("mean") || !spec.contains("sd")) return r.fail(what + ": normal needs mean and sd");
        if (!r.number(spec["mean"], what + ".mean", out.distribution.a) ||
            !r.number(spec["sd"], what + ".sd", out.distribution.b))
            return false;
        if (out.distribution.b < 0) return r.fail(what + ".sd must not be negative");
    } else if (kind == "uniform") {
        out.distribution.kind = Distribution::Kind::Uniform;
        if (!spec.contains("min") || !spec.contains("max")) return r.fail(what + ": uniform needs min and max");
        if (!r.number(spec["min"], what + ".min", out.distribution.a) ||
            !r.number(spec["max"], what + ".max", out.distribution.b))
            return false;
        if (!(out.distribution.a <= out.distribution.b)) return r.fail(what + ": min must not be above max");
    } else {
        return r.fail(what + ".distribution '" + kind + "' is not normal or uniform");
    }
    return true;
}

bool readSensitivity(Reader& r, const Json& body, StudyRequest& out)
{
    if (!body.contains("sensitivity")) return r.fail("a sensitivity study needs \"sensitivity\": {runs, parameters}");
    const Json& s = body["sensitivity"];
    if (!r.object(s, "sensitivity")) return false;
    if (!s.contains("runs")) return r.fail("sensitivity.runs is missing");
    if (!r.count(s["runs"], "sensitivity.runs", out.runs, std::numeric_limits<std::uint32_t>::max())) return false;
    if (out.runs < 2) return r.fail("sensitivity.runs must be at least 2");
    if (!r.seed(s, out.seed)) return false;
    if (!s.contains("parameters") || !r.object(s["parameters"], "sensitivity.parameters") ||
        s["parameters"].empty() || s["parameters"].size() > kMaxParameters)
        return r.fail("sensitivity.parameters must name 1 to " + std::to_string(kMaxParameters) + " parameters");
    for (const auto& [name, spec] : s["parameters"].items()) {
        RandomParameter parameter;
        if (!r.parameterName(name, "sensitivity.parameters") || !readDistribution(r, name, spec, parameter))
            return false;
        out.distributions.push_back(std::move(parameter));
    }
    if (out.outputs.variables.empty()) return r.fail("a sensitivity study needs outputs.variables");
    return true;
}

// "time,value" lines (a header line that is not numbers is skipped).
bool readReferenceCsv(Reader& r, const std::string& text, std::vector<std::pair<double, double>>& out)
{
    std::istringstream in(text);
    std::string line;
    std::size_t lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        const std::size_t comma = line.find(',');
        char* end = nullptr;
        const double t = std::strtod(line.c_str(), &end);
        const bool timeOk = comma != std::string::npos && end == line.c_str() + comma;
        double v = 0;
        bool valueOk = false;
        if (timeOk) {
            const char* valueStart = line.c_str() + comma + 1;
            v = std::strtod(valueStart, &end);
            valueOk = end != valueStart && *end == '\0';
        }
        if (!timeOk || !valueOk) {
            if (lineNumber == 1) continue;   // a header
            return r.fail("reference_csv line " + std::to_string(lineNumber) + " is not 'time,value'");
        }
        if (!out.empty() && !(t > out.back().first))
            return r.fail("reference_csv: times must increase (line " + std::to_string(lineNumber) + ")");
        out.emplace_back(t, v);
        if (out.size() > kMaxReferencePoints) return r.fail("reference_csv: too many lines");
    }
    if (out.empty()) return r.fail("reference_csv has no 'time,value' lines");
    return true;
}

bool readTerm(Reader& r, const Json& spec, ObjectiveTerm& term)
{
    if (!r.object(spec, "objective.terms[]")) return false;
    std::string function;
    if (!spec.contains("function") || !r.text(spec["function"], "objective.terms[].function", function)) return false;
    using F = ObjectiveTerm::Function;
    const std::pair<const char*, F> functions[] = {{"final", F::Final}, {"min", F::Min},
                                                   {"max", F::Max},     {"mean", F::Mean},
                                                   {"overshoot", F::Overshoot}, {"ise", F::Ise}};
    bool known = false;
    for (const auto& [name, f] : functions) {
        if (function == name) {
            term.function = f;
            known = true;
        }
    }
    if (!known) return r.fail("objective function '" + function + "' is not one of final, min, max, mean, overshoot, ise");
    if (!spec.contains("variable") || !r.text(spec["variable"], "objective.terms[].variable", term.variable)) return false;
    if (spec.contains("weight") && !r.number(spec["weight"], "objective.terms[].weight", term.weight)) return false;
    if (spec.contains("target")) {
        double target = 0;
        if (term.function == F::Overshoot || term.function == F::Ise)
            return r.fail("objective: target applies to final, min, max and mean");
        if (!r.number(spec["target"], "objective.terms[].target", target)) return false;
        term.target = target;
    }
    if (term.function == F::Ise) {
        const bool byVariable = spec.contains("reference_variable");
        const bool byCsv = spec.contains("reference_csv");
        if (byVariable == byCsv) return r.fail("objective ise needs reference_variable or reference_csv (one of them)");
        if (byVariable) return r.text(spec["reference_variable"], "objective.terms[].reference_variable", term.referenceVariable);
        std::string csv;
        return r.text(spec["reference_csv"], "objective.terms[].reference_csv", csv) &&
               readReferenceCsv(r, csv, term.referenceCurve);
    }
    return true;
}

bool readObjective(Reader& r, const Json& objective, StudyObjective& out)
{
    if (!r.object(objective, "objective")) return false;
    std::string goal = "minimise";
    if (objective.contains("goal") && !r.text(objective["goal"], "objective.goal", goal)) return false;
    if (goal != "minimise" && goal != "maximise") return r.fail("objective.goal must be minimise or maximise");
    out.maximise = goal == "maximise";
    if (!objective.contains("terms") || !objective["terms"].is_array() || objective["terms"].empty() ||
        objective["terms"].size() > kMaxObjectiveTerms)
        return r.fail("objective.terms must list 1 to " + std::to_string(kMaxObjectiveTerms) + " terms");
    for (const Json& spec : objective["terms"]) {
        ObjectiveTerm term;
        if (!readTerm(r, spec, term)) return false;
        out.terms.push_back(std::move(term));
    }
    return true;
}

bool readOptimise(Reader& r, const Json& body, StudyRequest& out)
{
    if (!body.contains("optimise")) return r.fail("an optimisation needs \"optimise\": {parameters, objective}");
    const Json& o = body["optimise"];
    if (!r.object(o, "optimise")) return false;
    OptimiserSettings& settings = out.optimiser;
    std::string algorithm = "complex-rf";
    if (o.contains("algorithm") && !r.text(o["algorithm"], "optimise.algorithm", algorithm)) return false;
    if (!optimiserAlgorithmFromName(algorithm, settings.algorithm))
        return r.fail("optimise.algorithm '" + algorithm + "' is not one of complex-rf, nelder-mead, particle-swarm");
    if (!o.contains("parameters") || !r.object(o["parameters"], "optimise.parameters") || o["parameters"].empty() ||
        o["parameters"].size() > kMaxParameters)
        return r.fail("optimise.parameters must give 1 to " + std::to_string(kMaxParameters) + " parameters {min, max}");
    for (const auto& [name, spec] : o["parameters"].items()) {
        const std::string what = "optimise.parameters." + name;
        ParameterBounds bounds;
        bounds.name = name;
        if (!r.parameterName(name, "optimise.parameters") || !r.object(spec, what)) return false;
        if (!spec.contains("min") || !spec.contains("max")) return r.fail(what + " needs min and max");
        if (!r.number(spec["min"], what + ".min", bounds.min) || !r.number(spec["max"], what + ".max", bounds.max))
            return false;
        if (spec.contains("start")) {
            double start = 0;
            if (!r.number(spec["start"], what + ".start", start)) return false;
            bounds.start = start;
        }
        settings.parameters.push_back(std::move(bounds));
    }
    if (o.contains("max_evaluations") &&
        !r.count(o["max_evaluations"], "optimise.max_evaluations", settings.maxEvaluations,
                 std::numeric_limits<std::uint32_t>::max()))
        return false;
    if (!r.seed(o, settings.seed)) return false;
    if (o.contains("tolerance") && !r.number(o["tolerance"], "optimise.tolerance", settings.tolerance)) return false;
    if (o.contains("options")) {
        if (!r.object(o["options"], "optimise.options")) return false;
        for (const auto& [name, value] : o["options"].items()) {
            double v = 0;
            if (!r.number(value, "optimise.options." + name, v)) return false;
            settings.options[name] = v;
        }
    }
    if (std::string problem = validateOptimiserSettings(settings); !problem.empty())
        return r.fail("optimise: " + problem);

    if (!o.contains("objective")) return r.fail("optimise.objective must give {goal, terms}");
    return readObjective(r, o["objective"], out.objective.emplace());
}

} // namespace

const char* studyKindName(StudyKind kind)
{
    switch (kind) {
    case StudyKind::Sweep: return "sweep";
    case StudyKind::Sensitivity: return "sensitivity";
    case StudyKind::Optimise: return "optimise";
    }
    return "sweep";
}

const char* runStatisticName(RunStatistic statistic)
{
    switch (statistic) {
    case RunStatistic::Final: return "final";
    case RunStatistic::Min: return "min";
    case RunStatistic::Max: return "max";
    case RunStatistic::Mean: return "mean";
    }
    return "final";
}

std::vector<std::string> StudyOutputs::columnNames() const
{
    std::vector<std::string> names;
    for (const std::string& variable : variables)
        for (RunStatistic statistic : statistics) names.push_back(variable + ":" + runStatisticName(statistic));
    return names;
}

std::vector<std::string> StudyRequest::parameterNames() const
{
    std::vector<std::string> names;
    switch (kind) {
    case StudyKind::Sweep:
        for (const SweepAxis& axis : axes) names.push_back(axis.name);
        break;
    case StudyKind::Sensitivity:
        for (const RandomParameter& p : distributions) names.push_back(p.name);
        break;
    case StudyKind::Optimise:
        for (const ParameterBounds& p : optimiser.parameters) names.push_back(p.name);
        break;
    }
    return names;
}

std::size_t StudyRequest::plannedRuns() const
{
    switch (kind) {
    case StudyKind::Sweep: return sweepSize(axes, mode, samples);
    case StudyKind::Sensitivity: return runs;
    case StudyKind::Optimise: return optimiser.maxEvaluations;
    }
    return 0;
}

bool parseStudyRequest(const nlohmann::json& body, StudyRequest& out, std::string& error)
{
    Reader r;
    out = StudyRequest{};
    const bool ok = [&] {
        if (!r.object(body, "the study")) return false;
        std::string kind;
        if (!body.contains("kind") || !r.text(body["kind"], "kind", kind)) return r.fail("kind must be sweep, sensitivity or optimise");
        if (kind == "sweep") out.kind = StudyKind::Sweep;
        else if (kind == "sensitivity") out.kind = StudyKind::Sensitivity;
        else if (kind == "optimise" || kind == "optimize") out.kind = StudyKind::Optimise;
        else return r.fail("kind '" + kind + "' is not one of sweep, sensitivity, optimise");
        if (body.contains("name") && !r.text(body["name"], "name", out.name)) return false;
        if (out.name.size() > 200) return r.fail("name: at most 200 characters");
        if (body.contains("model_id")) {
            if (!body["model_id"].is_number_integer()) return r.fail("model_id must be a whole number");
            out.modelId = body["model_id"].get<std::int64_t>();
        }
        if (body.contains("hmf") && !r.text(body["hmf"], "hmf", out.hmf)) return false;
        if (out.modelId.has_value() == !out.hmf.empty()) return r.fail("give model_id or hmf (one of them)");
        if (!readSettings(r, body, out.settings) || !readFixedParameters(r, body, out.fixedParameters) ||
            !readOutputs(r, body, out.outputs))
            return false;
        if (body.contains("max_failed_fraction")) {
            if (!r.number(body["max_failed_fraction"], "max_failed_fraction", out.maxFailedFraction)) return false;
            if (!(out.maxFailedFraction >= 0.0 && out.maxFailedFraction <= 1.0))
                return r.fail("max_failed_fraction must be from 0 to 1");
        }
        if (body.contains("objective")) {
            if (out.kind == StudyKind::Optimise) return r.fail("an optimisation's objective goes in optimise.objective");
            if (!readObjective(r, body["objective"], out.objective.emplace())) return false;
        }
        switch (out.kind) {
        case StudyKind::Sweep: return readSweep(r, body, out);
        case StudyKind::Sensitivity: return readSensitivity(r, body, out);
        case StudyKind::Optimise: return readOptimise(r, body, out);
        }
        return false;
    }();
    if (!ok) error = r.error.empty() ? "invalid study" : r.error;
    return ok;
}

} // namespace tlmhub::server
