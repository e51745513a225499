#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/WhiteGaussianNoise.h"

using namespace tlmhub;

TEST(WhiteGaussianNoise, UsesTwoRandDrawsCosineBranch)
{
    std::srand(12345);
    const double r1 = static_cast<double>(std::rand()) / static_cast<double>(RAND_MAX);
    const double r2 = static_cast<double>(std::rand()) / static_cast<double>(RAND_MAX);
    ASSERT_NE(r1, 0.0);
    const double expected = std::sqrt(-2.0 * std::log(r1)) * std::cos(2.0 * pi * r2);
    std::srand(12345);
    EXPECT_EQ(WhiteGaussianNoise::getValue(), expected);
}

TEST(WhiteGaussianNoise, StandardNormalStatistics)
{
    std::srand(1);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    int within1 = 0;
    for (int i = 0; i < n; ++i) {
        const double v = WhiteGaussianNoise::getValue();
        sum += v;
        sum2 += v * v;
        if (std::fabs(v) < 1.0) { ++within1; }
    }
    const double mean = sum / n;
    const double var = sum2 / n - mean * mean;
    // Standard errors: mean ~0.0022, variance ~0.0032; 5 sigma bounds.
    EXPECT_NEAR(mean, 0.0, 0.012);
    EXPECT_NEAR(var, 1.0, 0.016);
    EXPECT_NEAR(static_cast<double>(within1) / n, 0.6827, 0.006);
}
