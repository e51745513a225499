#include "server/studies/Optimiser.h"

#include "server/studies/ComplexRF.h"
#include "server/studies/NelderMead.h"
#include "server/studies/ParameterSampling.h"
#include "server/studies/ParticleSwarm.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace tlmhub::server {

namespace {

// Complexes, simplices and swarms larger than this are refused: a study has at most
// --max-study-runs (10000) evaluations anyway.
constexpr double kMaxPopulation = 10000;

bool isWholeNumber(double value)
{
    return std::floor(value) == value;
}

std::string formatNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// What is wrong with one option's value, or empty.
std::string checkOption(const OptimiserSettings& settings, const std::string& name, double value)
{
    const double parameters = static_cast<double>(settings.parameters.size());
    const std::string prefix = "option \"" + name + "\" ";
    switch (settings.algorithm) {
    case OptimiserAlgorithm::ComplexRF:
        if (name == "alpha" && !(value > 0.0)) return prefix + "must be above 0";
        if (name == "randomisation" && !(value >= 0.0)) return prefix + "must be 0 or more";
        if (name == "forgetting" && !(value >= 0.0)) return prefix + "must be 0 or more";
        if (name == "points" && !(isWholeNumber(value) && value >= parameters + 1 && value <= kMaxPopulation))
            return prefix + "must be a whole number from parameters + 1 (" + formatNumber(parameters + 1) +
                   ") to " + formatNumber(kMaxPopulation);
        return {};
    case OptimiserAlgorithm::NelderMead:
        if (name == "alpha" && !(value > 0.0)) return prefix + "must be above 0";
        if (name == "gamma" && !(value > 1.0)) return prefix + "must be above 1";
        if (name == "rho" && !(value > 0.0 && value < 1.0)) return prefix + "must be between 0 and 1";
        if (name == "sigma" && !(value > 0.0 && value < 1.0)) return prefix + "must be between 0 and 1";
        if (name == "restarts" && !(isWholeNumber(value) && value >= 0.0 && value <= 1000.0))
            return prefix + "must be a whole number from 0 to 1000";
        return {};
    case OptimiserAlgorithm::ParticleSwarm:
        if (name == "particles" && !(isWholeNumber(value) && value >= 2 && value <= kMaxPopulation))
            return prefix + "must be a whole number from 2 to " + formatNumber(kMaxPopulation);
        if ((name == "omega" || name == "c1" || name == "c2") && !(value >= 0.0))
            return prefix + "must be 0 or more";
        return {};
    }
    return {};
}

const std::set<std::string>& knownOptions(OptimiserAlgorithm algorithm)
{
    static const std::set<std::string> complexRF{"alpha", "randomisation", "forgetting", "points"};
    static const std::set<std::string> nelderMead{"alpha", "gamma", "rho", "sigma", "restarts"};
    static const std::set<std::string> particleSwarm{"particles", "omega", "c1", "c2"};
    switch (algorithm) {
    case OptimiserAlgorithm::ComplexRF: return complexRF;
    case OptimiserAlgorithm::NelderMead: return nelderMead;
    case OptimiserAlgorithm::ParticleSwarm: return particleSwarm;
    }
    return complexRF;
}

std::string checkParameters(const std::vector<ParameterBounds>& parameters)
{
    if (parameters.empty()) return "at least one parameter is needed";
    std::set<std::string> names;
    for (const auto& p : parameters) {
        if (p.name.empty()) return "a parameter has no name";
        if (!names.insert(p.name).second) return "parameter \"" + p.name + "\" is given twice";
        if (!std::isfinite(p.min) || !std::isfinite(p.max))
            return "parameter \"" + p.name + "\": min and max must be finite";
        if (!(p.min < p.max)) return "parameter \"" + p.name + "\": min must be below max";
        if (p.start && !(*p.start >= p.min && *p.start <= p.max))
            return "parameter \"" + p.name + "\": start must be within [min, max]";
    }
    return {};
}

} // namespace

bool optimiserAlgorithmFromName(const std::string& name, OptimiserAlgorithm& out)
{
    for (auto algorithm : {OptimiserAlgorithm::ComplexRF, OptimiserAlgorithm::NelderMead,
                           OptimiserAlgorithm::ParticleSwarm}) {
        if (name == optimiserAlgorithmName(algorithm)) {
            out = algorithm;
            return true;
        }
    }
    return false;
}

const char* optimiserAlgorithmName(OptimiserAlgorithm algorithm)
{
    switch (algorithm) {
    case OptimiserAlgorithm::ComplexRF: return "complex-rf";
    case OptimiserAlgorithm::NelderMead: return "nelder-mead";
    case OptimiserAlgorithm::ParticleSwarm: return "particle-swarm";
    }
    return "unknown";
}

std::string validateOptimiserSettings(const OptimiserSettings& settings)
{
    if (auto error = checkParameters(settings.parameters); !error.empty()) return error;
    if (settings.maxEvaluations == 0) return "max_evaluations must be at least 1";
    if (!(std::isfinite(settings.tolerance) && settings.tolerance >= 0.0))
        return "tolerance must be a finite number, 0 or more";
    const auto& known = knownOptions(settings.algorithm);
    for (const auto& [name, value] : settings.options) {
        if (!known.contains(name))
            return "unknown option \"" + name + "\" for " + optimiserAlgorithmName(settings.algorithm);
        if (!std::isfinite(value)) return "option \"" + name + "\" must be finite";
        if (auto error = checkOption(settings, name, value); !error.empty()) return error;
    }
    // Complex-RF ages values by 1 - (alpha/2)^(forgetting/points), which is 0 or negative
    // (old values would grow better) from alpha = 2 on.
    if (settings.algorithm == OptimiserAlgorithm::ComplexRF && optionOr(settings, "forgetting", 0.0) > 0.0 &&
        optionOr(settings, "alpha", ComplexRF::kDefaultAlpha) >= 2.0)
        return "option \"alpha\" must be below 2 when \"forgetting\" is used";
    return {};
}

std::unique_ptr<Optimiser> makeOptimiser(const OptimiserSettings& settings)
{
    switch (settings.algorithm) {
    case OptimiserAlgorithm::ComplexRF: return std::make_unique<ComplexRF>(settings);
    case OptimiserAlgorithm::NelderMead: return std::make_unique<NelderMead>(settings);
    case OptimiserAlgorithm::ParticleSwarm: return std::make_unique<ParticleSwarm>(settings);
    }
    return nullptr;
}

double optionOr(const OptimiserSettings& settings, const std::string& name, double fallback)
{
    auto it = settings.options.find(name);
    return it == settings.options.end() ? fallback : it->second;
}

Point clampIntoBounds(Point point, const std::vector<ParameterBounds>& parameters)
{
    for (std::size_t j = 0; j < point.size(); ++j) point[j] = std::clamp(point[j], parameters[j].min, parameters[j].max);
    return point;
}

Point randomPointInBounds(std::mt19937_64& random, const std::vector<ParameterBounds>& parameters, bool useStart)
{
    Point point(parameters.size());
    for (std::size_t j = 0; j < point.size(); ++j) {
        const auto& p = parameters[j];
        // Drawn even when the start is used, so the start does not shift later draws.
        const double drawn = p.min + (p.max - p.min) * uniformUnit(random);
        point[j] = useStart && p.start ? *p.start : drawn;
    }
    return point;
}

double relativeParameterSpread(const std::vector<Point>& points, const std::vector<ParameterBounds>& parameters)
{
    double spread = 0.0;
    for (std::size_t j = 0; j < parameters.size(); ++j) {
        auto [lowest, highest] = std::minmax_element(points.begin(), points.end(),
                                                     [j](const Point& a, const Point& b) { return a[j] < b[j]; });
        spread = std::max(spread, ((*highest)[j] - (*lowest)[j]) / (parameters[j].max - parameters[j].min));
    }
    return spread;
}

bool objectiveSpreadWithin(const std::vector<double>& values, double tolerance)
{
    if (values.empty() || !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
        return false;
    auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
    return *highest - *lowest <= tolerance * std::max(std::abs(*lowest), std::abs(*highest));
}

bool convergedWithin(const std::vector<Point>& points, const std::vector<double>& values,
                     const std::vector<ParameterBounds>& parameters, double tolerance)
{
    return objectiveSpreadWithin(values, tolerance) || relativeParameterSpread(points, parameters) < tolerance;
}

std::vector<double> EvaluationRecord::record(const std::vector<Point>& batch, const std::vector<double>& values)
{
    if (batch.empty() || values.size() != batch.size())
        throw std::invalid_argument("an optimiser was told " + std::to_string(values.size()) +
                                    " values for a batch of " + std::to_string(batch.size()));
    std::vector<double> used(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        used[i] = std::isnan(values[i]) ? std::numeric_limits<double>::infinity() : values[i];
        if (used[i] < mBestValue || mBest.empty()) {
            mBest = batch[i];
            mBestValue = used[i];
        }
    }
    mEvaluations += values.size();
    return used;
}

} // namespace tlmhub::server
