#pragma once
// Optimisation algorithms for studies (kind "optimise"), in ask/tell form so that the
// evaluations of one batch run in parallel on the job queue's workers:
//
//   auto optimiser = makeOptimiser(settings);       // always minimises
//   while (!optimiser->finished()) {
//       std::vector<Point> batch = optimiser->ask(); // points to evaluate, in order
//       std::vector<double> values = evaluateAll(batch);
//       optimiser->tell(values);                     // the batch's objective values, same order
//   }
//
// A batch is told as a whole, so a fixed seed gives the same trace however the evaluations
// were scheduled. Parameters are searched within their bounds; an objective that could not be
// evaluated (a failed run) is told as +infinity.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace tlmhub::server {

using Point = std::vector<double>;

struct ParameterBounds {
    std::string name;
    double min = 0.0, max = 1.0;
    // A starting value within bounds: Nelder-Mead's first vertex, Complex-RF's first point,
    // the swarm's first particle (the middle of the bounds, or random, when absent).
    std::optional<double> start;
};

enum class OptimiserAlgorithm { ComplexRF, NelderMead, ParticleSwarm };
// "complex-rf", "nelder-mead", "particle-swarm"; false for another name.
bool optimiserAlgorithmFromName(const std::string& name, OptimiserAlgorithm& out);
const char* optimiserAlgorithmName(OptimiserAlgorithm algorithm);

struct OptimiserSettings {
    OptimiserAlgorithm algorithm = OptimiserAlgorithm::ComplexRF;
    std::vector<ParameterBounds> parameters;
    std::size_t maxEvaluations = 200;
    std::uint64_t seed = 1;
    // Converged when the spread of the objective values over the complex / simplex / swarm is
    // below this (relative to their magnitude), or the parameter spread below it (relative
    // to the bounds).
    double tolerance = 1e-4;
    // Algorithm options by name (unknown names are refused by validateOptimiserSettings);
    // docs/optimisation.md says what each does:
    //   complex-rf: "alpha" (reflection, 1.3), "randomisation" (0.3), "forgetting" (0.0),
    //               "points" (complex size, 2 × parameters and at least 3)
    //   nelder-mead: "alpha" (1), "gamma" (2), "rho" (0.5), "sigma" (0.5), "restarts" (3: fresh
    //                simplices at random points after it has converged, for other valleys)
    //   particle-swarm: "particles" (20), "omega" (0.7), "c1" (1.5), "c2" (1.5)
    std::map<std::string, double> options;
};

// Empty when the settings are usable, else what is wrong (for the API's 400).
std::string validateOptimiserSettings(const OptimiserSettings& settings);

class Optimiser {
public:
    virtual ~Optimiser() = default;
    // The next batch; empty when finished (or, never in practice, while a batch is untold).
    virtual std::vector<Point> ask() = 0;
    // The objective values of the batch the last ask() returned, in its order (NaN counts as
    // +infinity). Throws std::invalid_argument when no batch is untold or the sizes differ.
    virtual void tell(const std::vector<double>& values) = 0;
    // Converged or out of evaluations.
    virtual bool finished() const = 0;
    // "converged" or "evaluation budget used" once finished.
    virtual std::string finishReason() const = 0;
    // Best point told so far and its value (+infinity before any).
    virtual Point best() const = 0;
    virtual double bestValue() const = 0;
    virtual std::size_t evaluations() const = 0;   // told so far
};

// Requires validateOptimiserSettings(settings) to be empty.
std::unique_ptr<Optimiser> makeOptimiser(const OptimiserSettings& settings);

// ---- Building blocks the algorithms share (Optimiser.cpp) ----

// The option `name`, or `fallback` when it is not set.
double optionOr(const OptimiserSettings& settings, const std::string& name, double fallback);
// `point` with each value moved into its parameter's [min, max].
Point clampIntoBounds(Point point, const std::vector<ParameterBounds>& parameters);
// Each value uniform in its parameter's bounds, except that a parameter's `start` is used
// when `useStart` is set.
Point randomPointInBounds(std::mt19937_64& random, const std::vector<ParameterBounds>& parameters,
                          bool useStart);
// The largest spread (max - min over `points`) of any parameter, relative to its range.
double relativeParameterSpread(const std::vector<Point>& points, const std::vector<ParameterBounds>& parameters);
// Whether max - min of `values` is at most `tolerance` times their largest magnitude; false
// while any value is not finite (a failed run is never "converged" on).
bool objectiveSpreadWithin(const std::vector<double>& values, double tolerance);
// The convergence rule of all three algorithms (OptimiserSettings::tolerance).
bool convergedWithin(const std::vector<Point>& points, const std::vector<double>& values,
                     const std::vector<ParameterBounds>& parameters, double tolerance);

// The best point told so far and the number of evaluations: what every algorithm reports.
class EvaluationRecord {
public:
    // Records a told batch (NaN as +infinity) and returns its values as the algorithm uses
    // them; throws std::invalid_argument when the sizes differ.
    std::vector<double> record(const std::vector<Point>& batch, const std::vector<double>& values);
    const Point& best() const { return mBest; }
    double bestValue() const { return mBestValue; }
    std::size_t evaluations() const { return mEvaluations; }

private:
    Point mBest;
    double mBestValue = std::numeric_limits<double>::infinity();
    std::size_t mEvaluations = 0;
};

} // namespace tlmhub::server
