#include "server/labs/LabChecks.h"

#include "server/studies/RunMeasures.h"

#include "core/Validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tlmhub::server {

namespace {

using Json = nlohmann::json;

constexpr const char* kMeasures[] = {"final", "min", "max", "overshoot", "settling_time", "rise_time"};

// Reads the definition field by field; the first problem found is kept, named by its field.
class DefinitionReader {
public:
    std::string error;

    bool fail(const std::string& field, const std::string& message)
    {
        if (error.empty()) error = "definition" + (field.empty() ? "" : "." + field) + ": " + message;
        return false;
    }
    bool number(const Json& j, const std::string& field, double& out)
    {
        if (!j.is_number()) return fail(field, "must be a number");
        out = j.get<double>();
        if (!std::isfinite(out)) return fail(field, "must be finite");
        return true;
    }
};

bool allowedField(const std::string& kind, const std::string& measure, const std::string& field)
{
    if (field == "kind" || field == "variable") return true;
    if (kind == "curve") return field == "tolerance" || field == "scale";
    if (field == "band") return measure == "settling_time";
    return field == "measure" || field == "min" || field == "max";
}

std::string format(const char* pattern, double value)
{
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// The samples of a column that have a time (a column logged late is shorter than the time).
std::span<const double> samples(const ResultTable& table, const ResultColumn& column)
{
    return std::span<const double>(column.data).first(std::min(column.data.size(), table.time.size()));
}

std::string notFiniteMessage(const std::string& variable, double t)
{
    return "'" + variable + "' is not a finite number at t = " + format("%g", t) + " s";
}

// "scale": "range": each sample may differ from the reference by the tolerance times the
// reference's largest magnitude at the run's times, one yardstick for the whole curve.
void judgeCurveByRange(const CheckDefinition& d, const std::vector<double>& time, std::span<const double> values,
                       const std::vector<double>& refTime, const std::vector<double>& refData, CheckOutcome& out)
{
    std::vector<double> refAtRun(values.size());
    double magnitude = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            out.message = notFiniteMessage(d.variable, time[i]);
            return;
        }
        refAtRun[i] = interpolateReference(refTime, refData, time[i]);
        // A NaN in the reference would drop out of the largest magnitude and let anything pass.
        if (!std::isfinite(refAtRun[i])) {
            out.message = "the reference run's " + notFiniteMessage(d.variable, time[i]);
            return;
        }
        magnitude = std::max(magnitude, std::fabs(refAtRun[i]));
    }
    double worstDifference = -1.0, worstTime = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double difference = std::fabs(values[i] - refAtRun[i]);
        if (difference > worstDifference) {
            worstDifference = difference;
            worstTime = time[i];
        }
    }
    // A reference that is zero throughout leaves no room: only an exact match passes.
    const double deviation = magnitude > 0.0 ? worstDifference / magnitude
                             : worstDifference > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    out.deviation = deviation;
    out.worstTime = worstTime;
    out.passed = worstDifference <= d.tolerance * magnitude;
    if (!out.passed)
        out.message = d.variable + " differs by " + format("%.3g", deviation * 100.0) +
                      " % of the reference's largest magnitude (" + format("%g", magnitude) + ") at t = " +
                      format("%g", worstTime) + " s (tolerance " + format("%g", d.tolerance * 100.0) + " %)";
}

void judgeCurve(const CheckDefinition& d, const ResultTable& run, const ResultTable* reference, CheckOutcome& out)
{
    const ResultColumn* runColumn = run.column(d.variable);
    if (!runColumn) {
        out.message = "the run has no variable '" + d.variable + "'";
        return;
    }
    if (!reference) {
        out.message = "there is no reference run to compare '" + d.variable + "' with";
        return;
    }
    const ResultColumn* refColumn = reference->column(d.variable);
    if (!refColumn) {
        out.message = "the reference run has no variable '" + d.variable + "'";
        return;
    }
    const auto values = samples(run, *runColumn);
    const auto refValues = samples(*reference, *refColumn);
    if (values.empty() || refValues.empty()) {
        out.message = "'" + d.variable + "' has no samples in the " + (values.empty() ? "run" : "reference run");
        return;
    }
    const std::vector<double> refTime(reference->time.begin(), reference->time.begin() + refValues.size());
    const std::vector<double> refData(refValues.begin(), refValues.end());
    if (d.scale == "range") {
        judgeCurveByRange(d, run.time, values, refTime, refData, out);
        return;
    }

    bool failed = false;
    double deviation = 0.0, worstTime = 0.0;
    bool compared = false;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double t = run.time[i];
        // The .hvc rule lets a NaN through (no comparison with it is true); a grade must not.
        if (!std::isfinite(values[i])) {
            out.message = notFiniteMessage(d.variable, t);
            return;
        }
        if (!std::isfinite(t)) {
            out.message = "the run's time is not a finite number at sample " + std::to_string(i + 1);
            return;
        }
        const double ref = interpolateReference(refTime, refData, t);
        failed = sampleFails(values[i], ref, d.tolerance) || failed;
        // The samples the rule compares (core.md §7.4); tiny values on either side are skipped.
        if (std::fabs(values[i]) < 1e-100 || std::fabs(ref) < 1e-10) continue;
        const double sampleDeviation = std::fabs(1.0 - values[i] / ref);
        if (!compared || sampleDeviation > deviation) {
            deviation = sampleDeviation;
            worstTime = t;
            compared = true;
        }
    }
    if (compared) {
        out.deviation = deviation;
        out.worstTime = worstTime;
    }
    out.passed = !failed;
    if (failed)
        out.message = d.variable + " differs by " + format("%.3g", deviation * 100.0) + " % at t = " +
                      format("%g", worstTime) + " s (tolerance " + format("%g", d.tolerance * 100.0) + " %)";
}

std::optional<double> measureOf(const CheckDefinition& d, std::span<const double> time, std::span<const double> values)
{
    if (d.measure == "final") return finalValue(values);
    if (d.measure == "min") return minValue(values);
    if (d.measure == "max") return maxValue(values);
    if (d.measure == "overshoot") return overshootPercent(values);
    if (d.measure == "settling_time") return settlingTime(time, values, d.band);
    return riseTime(time, values);
}

void judgeScalar(const CheckDefinition& d, const ResultTable& run, CheckOutcome& out)
{
    const ResultColumn* column = run.column(d.variable);
    if (!column) {
        out.message = "the run has no variable '" + d.variable + "'";
        return;
    }
    const auto values = samples(run, *column);
    if (values.empty()) {
        out.message = "'" + d.variable + "' has no samples in the run";
        return;
    }
    const auto value = measureOf(d, std::span<const double>(run.time).first(values.size()), values);
    if (!value) {
        out.message = "'" + d.variable + "' does not change, so it has no rise time";
        return;
    }
    if (!std::isfinite(*value)) {
        out.message = "the " + d.measure + " of '" + d.variable + "' is not a finite number";
        return;
    }
    out.value = *value;
    out.passed = (!d.min || *value >= *d.min) && (!d.max || *value <= *d.max);
    if (out.passed) return;
    const std::string unit = d.measure == "overshoot" ? " %" : d.measure.ends_with("_time") ? " s" : "";
    std::string bounds;
    if (d.min && d.max) bounds = "between " + format("%g", *d.min) + " and " + format("%g", *d.max) + unit;
    else if (d.min) bounds = "at least " + format("%g", *d.min) + unit;
    else bounds = "at most " + format("%g", *d.max) + unit;
    out.message = "the " + d.measure + " of " + d.variable + " is " + format("%g", *value) + unit + ", required " + bounds;
}

} // namespace

std::optional<CheckDefinition> parseCheckDefinition(const nlohmann::json& json, std::string& error)
{
    DefinitionReader r;
    CheckDefinition d;
    const auto done = [&]() -> std::optional<CheckDefinition> {
        error = r.error;
        return std::nullopt;
    };
    if (!json.is_object()) {
        r.fail("", "must be an object");
        return done();
    }
    if (!json.contains("kind") || !json["kind"].is_string()) {
        r.fail("kind", "must be curve or scalar");
        return done();
    }
    d.kind = json["kind"].get<std::string>();
    if (d.kind != "curve" && d.kind != "scalar") {
        r.fail("kind", "must be curve or scalar");
        return done();
    }
    if (!json.contains("variable") || !json["variable"].is_string() || json["variable"].get<std::string>().empty()) {
        r.fail("variable", "must be a non-empty string");
        return done();
    }
    d.variable = json["variable"].get<std::string>();

    if (d.kind == "scalar") {
        const auto& measure = json.contains("measure") ? json["measure"] : Json();
        if (measure.is_string()) d.measure = measure.get<std::string>();
        if (std::ranges::find(kMeasures, d.measure) == std::end(kMeasures)) {
            r.fail("measure", "must be one of final, min, max, overshoot, settling_time, rise_time");
            return done();
        }
    }
    // Checked after the measure, so a band on the wrong measure is named as such.
    for (const auto& [field, value] : json.items()) {
        if (allowedField(d.kind, d.measure, field)) continue;
        if (field == "band" && d.kind == "scalar") r.fail(field, "only for the measure settling_time");
        else r.fail(field, "unknown field for a " + d.kind + " check");
        return done();
    }

    if (d.kind == "curve") {
        if (json.contains("tolerance")) {
            if (!r.number(json["tolerance"], "tolerance", d.tolerance)) return done();
            if (d.tolerance <= 0) {
                r.fail("tolerance", "must be greater than 0");
                return done();
            }
        }
        if (json.contains("scale")) {
            const Json& scale = json["scale"];
            if (!scale.is_string() || (scale.get<std::string>() != "sample" && scale.get<std::string>() != "range")) {
                r.fail("scale", "must be sample or range");
                return done();
            }
            d.scale = scale.get<std::string>();
        }
        return d;
    }

    for (const auto& [field, bound] : {std::pair{"min", &d.min}, std::pair{"max", &d.max}}) {
        if (!json.contains(field)) continue;
        double value = 0;
        if (!r.number(json[field], field, value)) return done();
        *bound = value;
    }
    if (!d.min && !d.max) {
        r.fail("min", "a scalar check needs min, max or both");
        return done();
    }
    if (d.min && d.max && *d.min > *d.max) {
        r.fail("max", "must not be less than min");
        return done();
    }
    if (json.contains("band")) {
        if (!r.number(json["band"], "band", d.band)) return done();
        if (d.band <= 0 || d.band >= 1) {
            r.fail("band", "must be greater than 0 and less than 1");
            return done();
        }
    }
    return d;
}

nlohmann::json checkDefinitionJson(const CheckDefinition& definition)
{
    Json j = {{"kind", definition.kind}, {"variable", definition.variable}};
    if (definition.kind == "curve") {
        j["tolerance"] = definition.tolerance;
        // Absent stays absent: a check stored before the field existed reads back unchanged.
        if (!definition.scale.empty()) j["scale"] = definition.scale;
        return j;
    }
    j["measure"] = definition.measure;
    if (definition.min) j["min"] = *definition.min;
    if (definition.max) j["max"] = *definition.max;
    if (definition.measure == "settling_time") j["band"] = definition.band;
    return j;
}

std::vector<CheckOutcome> evaluateChecks(const std::vector<AssignmentCheck>& checks, const ResultTable& run,
                                         const ResultTable* reference, bool pretestsOnly)
{
    std::vector<CheckOutcome> outcomes;
    for (const AssignmentCheck& check : checks) {
        if (pretestsOnly && !check.pretest) continue;
        CheckOutcome& out = outcomes.emplace_back();
        out.name = check.name;
        out.pretest = check.pretest;
        out.points = check.points;
        // Definitions are checked when stored; one that no longer reads fails rather than throws.
        const Json json = Json::parse(check.definition, nullptr, false);
        std::string error;
        const auto definition = parseCheckDefinition(json, error);
        if (!definition) {
            out.message = "the check cannot be read: " + (json.is_discarded() ? "definition is not JSON" : error);
            continue;
        }
        if (definition->kind == "curve") judgeCurve(*definition, run, reference, out);
        else judgeScalar(*definition, run, out);
        out.awarded = out.passed ? out.points : 0.0;
    }
    return outcomes;
}

nlohmann::json outcomesJson(const std::vector<CheckOutcome>& outcomes)
{
    Json list = Json::array();
    for (const CheckOutcome& o : outcomes) {
        Json j = {{"name", o.name}, {"pretest", o.pretest}, {"passed", o.passed},
                  {"points", o.points}, {"awarded", o.awarded}};
        if (o.value) j["value"] = *o.value;
        if (o.deviation) j["deviation"] = *o.deviation;
        if (o.worstTime) j["worst_time"] = *o.worstTime;
        j["message"] = o.message;
        list.push_back(std::move(j));
    }
    return list;
}

nlohmann::json outcomesForStudent(const nlohmann::json& outcomes)
{
    if (!outcomes.is_array()) return Json::array();
    Json list = Json::array();
    for (const Json& o : outcomes) {
        if (o.value("pretest", false)) {
            list.push_back(o);
            continue;
        }
        Json shown = Json::object();
        for (const char* key : {"name", "pretest", "passed", "points", "awarded"})
            if (o.contains(key)) shown[key] = o[key];
        list.push_back(std::move(shown));
    }
    return list;
}

double settlingTime(std::span<const double> time, std::span<const double> values, double band)
{
    const std::size_t n = std::min(time.size(), values.size());
    if (n == 0) return std::numeric_limits<double>::quiet_NaN();
    const double final = values[n - 1];
    const double width = band * std::fabs(final - values[0]);
    // The last sample outside the band (a NaN counts as outside).
    std::size_t last = n;
    for (std::size_t i = n; i-- > 0;) {
        if (!(std::fabs(values[i] - final) <= width)) {
            last = i;
            break;
        }
    }
    if (last == n) return 0.0;
    if (last == n - 1) return std::numeric_limits<double>::quiet_NaN();
    // Where the straight line between the last sample outside and the next one enters the
    // band, measured from the first sample, so a run that never leaves it gives 0.
    const double e0 = values[last] - final, e1 = values[last + 1] - final;
    const double edge = e0 > 0 ? width : -width;
    const double fraction = std::isfinite(e0) ? (e0 - edge) / (e0 - e1) : 1.0;
    return time[last] + fraction * (time[last + 1] - time[last]) - time[0];
}

std::optional<double> riseTime(std::span<const double> time, std::span<const double> values)
{
    const std::size_t n = std::min(time.size(), values.size());
    if (n == 0) return std::nullopt;
    const double first = values[0], change = values[n - 1] - first;
    if (change == 0.0 || !std::isfinite(change)) return std::nullopt;
    // The first time the progress (0 at the first value, 1 at the final one) reaches `level`,
    // between samples by linear interpolation; the final sample always reaches it.
    const auto reaches = [&](double level) {
        for (std::size_t i = 1; i < n; ++i) {
            const double before = (values[i - 1] - first) / change, after = (values[i] - first) / change;
            if (after >= level)
                return time[i - 1] + (level - before) / (after - before) * (time[i] - time[i - 1]);
        }
        return time[n - 1];
    };
    return reaches(0.9) - reaches(0.1);
}

} // namespace tlmhub::server
