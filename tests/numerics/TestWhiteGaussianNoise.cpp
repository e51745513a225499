#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/RandomStream.h"
#include "core/numerics/WhiteGaussianNoise.h"

using namespace tlmhub;

// The reference draws its noise from glibc's rand(): the stream must give the same numbers
// for the same seed, including seed 1 (a fresh process) and after a reseed.
TEST(RandomStream, GivesTheNumbersOfGlibcRand)
{
    for (const unsigned seed : {1u, 12345u, 4000000000u}) {
        std::srand(seed);
        RandomStream stream(seed);
        for (int i = 0; i < 5000; ++i) ASSERT_EQ(stream.next(), std::rand()) << "seed " << seed << ", draw " << i;
    }
    RandomStream stream(7);
    const int first = stream.next();
    for (int i = 0; i < 100; ++i) stream.next();
    stream.reseed(7);
    EXPECT_EQ(stream.next(), first);
}

TEST(WhiteGaussianNoise, UsesTwoDrawsCosineBranch)
{
    RandomStream draws(12345);
    const double r1 = static_cast<double>(draws.next()) / static_cast<double>(RandomStream::kMax);
    const double r2 = static_cast<double>(draws.next()) / static_cast<double>(RandomStream::kMax);
    ASSERT_NE(r1, 0.0);
    const double expected = std::sqrt(-2.0 * std::log(r1)) * std::cos(2.0 * pi * r2);
    RandomStream stream(12345);
    EXPECT_EQ(WhiteGaussianNoise::getValue(stream), expected);
}

TEST(WhiteGaussianNoise, StandardNormalStatistics)
{
    RandomStream stream(1);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    int within1 = 0;
    for (int i = 0; i < n; ++i) {
        const double v = WhiteGaussianNoise::getValue(stream);
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
