#include "server/studies/RunMeasures.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tlmhub::server {

double finalValue(std::span<const double> values)
{
    return values.empty() ? std::numeric_limits<double>::quiet_NaN() : values.back();
}

double minValue(std::span<const double> values)
{
    return values.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::min_element(values.begin(), values.end());
}

double maxValue(std::span<const double> values)
{
    return values.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::max_element(values.begin(), values.end());
}

double timeAverage(std::span<const double> time, std::span<const double> values)
{
    const std::size_t n = std::min(time.size(), values.size());
    if (n == 0) return std::numeric_limits<double>::quiet_NaN();
    if (n == 1 || time[n - 1] == time[0]) return values[0];
    double integral = 0.0;
    for (std::size_t i = 1; i < n; ++i) integral += 0.5 * (values[i] + values[i - 1]) * (time[i] - time[i - 1]);
    return integral / (time[n - 1] - time[0]);
}

double overshootPercent(std::span<const double> values)
{
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double first = values.front(), last = values.back();
    const double change = last - first;
    if (change == 0.0) return 0.0;
    const double beyond = change > 0 ? maxValue(values) - last : last - minValue(values);
    return std::max(0.0, beyond) / std::abs(change) * 100.0;
}

double integralSquaredError(std::span<const double> time, std::span<const double> values,
                            std::span<const double> reference)
{
    const std::size_t n = std::min({time.size(), values.size(), reference.size()});
    double integral = 0.0;
    for (std::size_t i = 1; i < n; ++i) {
        const double e0 = values[i - 1] - reference[i - 1], e1 = values[i] - reference[i];
        integral += 0.5 * (e0 * e0 + e1 * e1) * (time[i] - time[i - 1]);
    }
    return integral;
}

double interpolate(const std::vector<std::pair<double, double>>& curve, double t)
{
    if (t <= curve.front().first) return curve.front().second;
    if (t >= curve.back().first) return curve.back().second;
    const auto after = std::upper_bound(curve.begin(), curve.end(), t,
                                        [](double x, const std::pair<double, double>& p) { return x < p.first; });
    const auto before = after - 1;
    const double fraction = (t - before->first) / (after->first - before->first);
    return before->second + fraction * (after->second - before->second);
}

namespace {

// A variable's samples, or nullopt with the error naming it.
std::optional<std::vector<double>> samplesOf(const ResultView& results, const std::string& name, std::string& error)
{
    auto data = results.data(name);
    if (!data) error = "the result has no variable '" + name + "'";
    return data;
}

double statistic(RunStatistic s, std::span<const double> time, std::span<const double> values)
{
    switch (s) {
    case RunStatistic::Final: return finalValue(values);
    case RunStatistic::Min: return minValue(values);
    case RunStatistic::Max: return maxValue(values);
    case RunStatistic::Mean: return timeAverage(time, values);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

std::optional<double> termValue(const ObjectiveTerm& term, const ResultView& results, std::string& error)
{
    const auto values = samplesOf(results, term.variable, error);
    if (!values) return std::nullopt;
    const std::span<const double> time = results.time();
    using F = ObjectiveTerm::Function;
    double value = 0.0;
    switch (term.function) {
    case F::Final: value = statistic(RunStatistic::Final, time, *values); break;
    case F::Min: value = statistic(RunStatistic::Min, time, *values); break;
    case F::Max: value = statistic(RunStatistic::Max, time, *values); break;
    case F::Mean: value = statistic(RunStatistic::Mean, time, *values); break;
    case F::Overshoot: return overshootPercent(*values);
    case F::Ise: {
        if (!term.referenceVariable.empty()) {
            const auto reference = samplesOf(results, term.referenceVariable, error);
            if (!reference) return std::nullopt;
            return integralSquaredError(time, *values, *reference);
        }
        std::vector<double> reference(time.size());
        for (std::size_t i = 0; i < time.size(); ++i) reference[i] = interpolate(term.referenceCurve, time[i]);
        return integralSquaredError(time, *values, reference);
    }
    }
    if (term.target) return (value - *term.target) * (value - *term.target);
    return value;
}

} // namespace

std::optional<std::vector<double>> runOutputs(const StudyOutputs& outputs, const ResultView& results,
                                              std::string& error)
{
    std::vector<double> row;
    row.reserve(outputs.variables.size() * outputs.statistics.size());
    for (const std::string& variable : outputs.variables) {
        const auto values = samplesOf(results, variable, error);
        if (!values) return std::nullopt;
        for (RunStatistic s : outputs.statistics) row.push_back(statistic(s, results.time(), *values));
    }
    return row;
}

std::optional<double> runObjective(const StudyObjective& objective, const ResultView& results, std::string& error)
{
    double sum = 0.0;
    for (const ObjectiveTerm& term : objective.terms) {
        const auto value = termValue(term, results, error);
        if (!value) return std::nullopt;
        sum += term.weight * *value;
    }
    return sum;
}

std::vector<std::string> variablesRead(const StudyRequest& request)
{
    std::vector<std::string> names = request.outputs.variables;
    if (request.objective) {
        for (const ObjectiveTerm& term : request.objective->terms) {
            names.push_back(term.variable);
            if (!term.referenceVariable.empty()) names.push_back(term.referenceVariable);
        }
    }
    return names;
}

} // namespace tlmhub::server
