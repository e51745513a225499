// The parameter sets of sweeps (grid, list, random) and Monte Carlo studies, and the
// statistics of sensitivity studies (SeriesBands, Pearson's r).
#include "server/studies/ParameterSampling.h"
#include "server/studies/StudyStatistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

using namespace tlmhub::server;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SweepAxis listAxis(std::string name, std::vector<double> values)
{
    return {std::move(name), std::move(values)};
}

SweepAxis rangeAxis(std::string name, double from, double to, std::size_t steps)
{
    return {std::move(name), SweepRange{from, to, steps}};
}

// Mean and sample standard deviation of `values`.
std::pair<double, double> meanAndSd(const std::vector<double>& values)
{
    double mean = 0.0;
    for (double v : values) mean += v;
    mean /= static_cast<double>(values.size());
    double squares = 0.0;
    for (double v : values) squares += (v - mean) * (v - mean);
    return {mean, std::sqrt(squares / static_cast<double>(values.size() - 1))};
}

} // namespace

TEST(ParameterSampling, GridVariesTheFirstAxisSlowest)
{
    const std::vector<SweepAxis> axes{listAxis("a", {1, 2}), rangeAxis("b", 10, 30, 3)};
    ASSERT_EQ(sweepSize(axes, SweepMode::Grid, 0), 6u);
    const std::vector<std::vector<double>> expected{{1, 10}, {1, 20}, {1, 30}, {2, 10}, {2, 20}, {2, 30}};
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(sweepPoint(axes, SweepMode::Grid, i, 0), expected[i]);
}

TEST(ParameterSampling, GridOfThreeAxesHasEveryCombinationOnce)
{
    const std::vector<SweepAxis> axes{listAxis("a", {1, 2, 3}), listAxis("b", {4, 5}), rangeAxis("c", 0, 1, 4)};
    const std::size_t size = sweepSize(axes, SweepMode::Grid, 0);
    ASSERT_EQ(size, 24u);
    std::set<std::vector<double>> seen;
    for (std::size_t i = 0; i < size; ++i) seen.insert(sweepPoint(axes, SweepMode::Grid, i, 0));
    EXPECT_EQ(seen.size(), 24u);
    EXPECT_EQ(sweepPoint(axes, SweepMode::Grid, 23, 0), (std::vector<double>{3, 5, 1}));
}

TEST(ParameterSampling, GridSizeSaturatesInsteadOfOverflowing)
{
    const std::vector<SweepAxis> axes(5, rangeAxis("x", 0, 1, 1000000));
    EXPECT_EQ(sweepSize(axes, SweepMode::Grid, 0), std::numeric_limits<std::size_t>::max());
}

TEST(ParameterSampling, EmptySweepsHaveNoSets)
{
    EXPECT_EQ(sweepSize({}, SweepMode::Grid, 0), 0u);
    EXPECT_EQ(sweepSize({}, SweepMode::Random, 10), 0u);
    const std::vector<SweepAxis> withEmptyAxis{listAxis("a", {1, 2}), listAxis("b", {})};
    EXPECT_EQ(sweepSize(withEmptyAxis, SweepMode::Grid, 0), 0u);
    EXPECT_EQ(sweepSize(withEmptyAxis, SweepMode::Random, 10), 0u);
    EXPECT_EQ(sweepSize({rangeAxis("a", 0, 1, 0)}, SweepMode::Grid, 0), 0u);
}

TEST(ParameterSampling, ListTakesTheIthValuesTogether)
{
    const std::vector<SweepAxis> axes{listAxis("a", {1, 2, 3}), rangeAxis("b", 0, 1, 3)};
    ASSERT_EQ(sweepSize(axes, SweepMode::List, 0), 3u);
    EXPECT_EQ(sweepPoint(axes, SweepMode::List, 0, 0), (std::vector<double>{1, 0}));
    EXPECT_EQ(sweepPoint(axes, SweepMode::List, 1, 0), (std::vector<double>{2, 0.5}));
    EXPECT_EQ(sweepPoint(axes, SweepMode::List, 2, 0), (std::vector<double>{3, 1}));
}

TEST(ParameterSampling, ListWithUnequalLengthsHasNoSets)
{
    const std::vector<SweepAxis> axes{listAxis("a", {1, 2, 3}), listAxis("b", {1, 2})};
    EXPECT_EQ(sweepSize(axes, SweepMode::List, 0), 0u);
}

TEST(ParameterSampling, RangeEndpointsAreExact)
{
    for (const auto& [from, to, steps] : {std::tuple{0.1, 0.7, 7u}, std::tuple{1e-5, 3.3e-5, 10u},
                                          std::tuple{-2.2, 1.9, 3u}, std::tuple{5.0, -0.3, 11u}}) {
        const auto values = axisValues(rangeAxis("x", from, to, steps));
        ASSERT_EQ(values.size(), steps);
        EXPECT_EQ(values.front(), from);
        EXPECT_EQ(values.back(), to);
        for (std::size_t i = 1; i < values.size(); ++i)
            EXPECT_NEAR(values[i] - values[i - 1], (to - from) / (steps - 1), 1e-12 * std::abs(to - from));
    }
}

TEST(ParameterSampling, OneStepIsTheStartOfTheRange)
{
    EXPECT_EQ(axisValues(rangeAxis("x", 3.5, 9, 1)), std::vector<double>{3.5});
    EXPECT_EQ(axisValues(listAxis("x", {4, 1, 7})), (std::vector<double>{4, 1, 7}));
}

TEST(ParameterSampling, RandomSetsDependOnlyOnSeedAndIndex)
{
    const std::vector<SweepAxis> axes{rangeAxis("a", -1, 3, 2), listAxis("b", {10, 20, 30})};
    ASSERT_EQ(sweepSize(axes, SweepMode::Random, 200), 200u);
    std::vector<std::vector<double>> forwards;
    for (std::size_t i = 0; i < 200; ++i) forwards.push_back(sweepPoint(axes, SweepMode::Random, i, 7));
    // Asked backwards (another evaluation order), each set is the same.
    for (std::size_t i = 200; i-- > 0;) EXPECT_EQ(sweepPoint(axes, SweepMode::Random, i, 7), forwards[i]);

    std::set<double> listValues;
    for (const auto& point : forwards) {
        EXPECT_GE(point[0], -1.0);
        EXPECT_LT(point[0], 3.0);
        EXPECT_TRUE(point[1] == 10 || point[1] == 20 || point[1] == 30);
        listValues.insert(point[1]);
    }
    EXPECT_EQ(listValues.size(), 3u);
    EXPECT_NE(forwards[0], forwards[1]);
    EXPECT_NE(sweepPoint(axes, SweepMode::Random, 0, 8), forwards[0]);
}

TEST(ParameterSampling, MonteCarloSamplesDependOnlyOnSeedAndIndex)
{
    const std::vector<RandomParameter> parameters{{"m", {Distribution::Kind::Normal, 100, 5}},
                                                  {"k", {Distribution::Kind::Uniform, 1e4, 2e4}}};
    const auto third = monteCarloPoint(parameters, 3, 7);
    EXPECT_EQ(monteCarloPoint(parameters, 9, 7).size(), 2u);
    EXPECT_EQ(monteCarloPoint(parameters, 3, 7), third);
    EXPECT_NE(monteCarloPoint(parameters, 3, 8), third);
    EXPECT_NE(monteCarloPoint(parameters, 4, 7), third);
}

// 20000 draws of normal(100, 5): the sample mean lies within 4 standard errors of 100
// (SE = 5 / sqrt(20000) = 0.035) and the sample sd within 4 of its standard errors of 5
// (about 5 / sqrt(2 × 20000) = 0.025). With a fixed seed the test is deterministic; another
// seed fails it with a probability of about 1e-4.
TEST(ParameterSampling, NormalSamplesHaveTheirMeanAndStandardDeviation)
{
    const std::vector<RandomParameter> parameters{{"m", {Distribution::Kind::Normal, 100, 5}}};
    constexpr std::size_t n = 20000;
    std::vector<double> values;
    for (std::size_t i = 0; i < n; ++i) values.push_back(monteCarloPoint(parameters, i, 7)[0]);
    const auto [mean, sd] = meanAndSd(values);
    EXPECT_NEAR(mean, 100.0, 4 * 5 / std::sqrt(n));
    EXPECT_NEAR(sd, 5.0, 4 * 5 / std::sqrt(2.0 * n));
    // About 68.3 % within one sd (binomial SE 0.33 %; 4 SE allowed).
    const auto withinOneSd = std::count_if(values.begin(), values.end(), [](double v) { return std::abs(v - 100) < 5; });
    EXPECT_NEAR(static_cast<double>(withinOneSd) / n, 0.6827, 4 * 0.0033);
}

// 20000 draws of uniform(1e4, 2e4): all within bounds, mean within 4 standard errors of 1.5e4
// (SE = 1e4 / sqrt(12 × 20000) = 20.4), sd within 2 % of 1e4 / sqrt(12).
TEST(ParameterSampling, UniformSamplesStayWithinBounds)
{
    const std::vector<RandomParameter> parameters{{"k", {Distribution::Kind::Uniform, 1e4, 2e4}}};
    constexpr std::size_t n = 20000;
    std::vector<double> values;
    for (std::size_t i = 0; i < n; ++i) {
        values.push_back(monteCarloPoint(parameters, i, 11)[0]);
        EXPECT_GE(values.back(), 1e4);
        EXPECT_LT(values.back(), 2e4);
    }
    const auto [mean, sd] = meanAndSd(values);
    EXPECT_NEAR(mean, 1.5e4, 4 * 1e4 / std::sqrt(12.0 * n));
    EXPECT_NEAR(sd, 1e4 / std::sqrt(12.0), 0.02 * 1e4 / std::sqrt(12.0));
}

TEST(ParameterSampling, UniformUnitIsWithinZeroAndOne)
{
    auto random = indexedGenerator(1, 0);
    for (int i = 0; i < 100000; ++i) {
        const double u = uniformUnit(random);
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
    }
}

TEST(StudyStatistics, SeriesBandsMatchATwoPassComputation)
{
    // Values with a large offset, where a one-pass sum of squares would lose digits.
    constexpr std::size_t runs = 50, samples = 100;
    std::vector<std::vector<double>> series(runs, std::vector<double>(samples));
    auto random = indexedGenerator(3, 0);
    for (auto& run : series)
        for (std::size_t t = 0; t < samples; ++t) run[t] = 1e6 + static_cast<double>(t) + standardNormal(random);

    SeriesBands bands;
    for (const auto& run : series) ASSERT_TRUE(bands.add(run));
    EXPECT_EQ(bands.count(), runs);
    const auto mean = bands.mean(), sd = bands.standardDeviation();
    ASSERT_EQ(mean.size(), samples);
    ASSERT_EQ(sd.size(), samples);
    for (std::size_t t = 0; t < samples; ++t) {
        std::vector<double> column;
        for (const auto& run : series) column.push_back(run[t]);
        const auto [expectedMean, expectedSd] = meanAndSd(column);
        EXPECT_NEAR(mean[t], expectedMean, 1e-9 * expectedMean);
        EXPECT_NEAR(sd[t], expectedSd, 1e-7 * expectedSd);
    }
}

TEST(StudyStatistics, SeriesBandsRefuseADifferentLength)
{
    SeriesBands bands;
    EXPECT_TRUE(bands.mean().empty());
    ASSERT_TRUE(bands.add({1, 2, 3}));
    EXPECT_EQ(bands.standardDeviation(), (std::vector<double>{0, 0, 0}));   // one series
    EXPECT_FALSE(bands.add({1, 2}));
    EXPECT_EQ(bands.count(), 1u);
    ASSERT_TRUE(bands.add({3, 2, 1}));
    EXPECT_EQ(bands.mean(), (std::vector<double>{2, 2, 2}));
    EXPECT_EQ(bands.standardDeviation(), (std::vector<double>{std::sqrt(2.0), 0, std::sqrt(2.0)}));
}

TEST(StudyStatistics, PearsonOfKnownData)
{
    // Mean x 3, mean y 4: Sxy = 6, Sxx = 10, Syy = 6, r = 6 / sqrt(60).
    EXPECT_DOUBLE_EQ(pearsonCorrelation({1, 2, 3, 4, 5}, {2, 4, 5, 4, 5}), 6 / std::sqrt(60.0));
}

TEST(StudyStatistics, PearsonOfPerfectLinesIsPlusOrMinusOne)
{
    const std::vector<double> x{0.1, 0.4, 2.5, 3.0, 7.5};
    std::vector<double> rising, falling;
    for (double v : x) {
        rising.push_back(3 * v + 2);
        falling.push_back(-0.5 * v + 1e3);
    }
    EXPECT_DOUBLE_EQ(pearsonCorrelation(x, rising), 1.0);
    EXPECT_DOUBLE_EQ(pearsonCorrelation(x, falling), -1.0);
}

TEST(StudyStatistics, PearsonOfAConstantOrTooFewPairsIsNaN)
{
    EXPECT_TRUE(std::isnan(pearsonCorrelation({1, 2, 3}, {5, 5, 5})));
    EXPECT_TRUE(std::isnan(pearsonCorrelation({4, 4, 4}, {1, 2, 3})));
    EXPECT_TRUE(std::isnan(pearsonCorrelation({1}, {2})));
    EXPECT_TRUE(std::isnan(pearsonCorrelation({}, {})));
    EXPECT_TRUE(std::isnan(pearsonCorrelation({1, 2, 3}, {1, 2})));
}

TEST(StudyStatistics, PearsonLeavesOutNonFinitePairs)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    // Without the non-finite pairs the rest lie on a line.
    EXPECT_DOUBLE_EQ(pearsonCorrelation({1, 2, 100, 3, kNaN, 4}, {2, 4, inf, 6, 0, 8}), 1.0);
    EXPECT_TRUE(std::isnan(pearsonCorrelation({1, kNaN, 3}, {inf, 2, 3})));   // one pair left
}
