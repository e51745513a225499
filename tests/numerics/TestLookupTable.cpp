#include <gtest/gtest.h>

#include <vector>

#include "core/numerics/LookupTable.h"

using namespace tlmhub;

TEST(LookupTable1D, InterpolatesAndExtrapolatesConstant)
{
    LookupTable1D t;
    t.getIndexDataRef(0) = {0.0, 1.0, 3.0};
    t.getValueDataRef() = {10.0, 20.0, 0.0};
    ASSERT_TRUE(t.isDataOK());
    EXPECT_EQ(t.interpolate(-5.0), 10.0);
    EXPECT_EQ(t.interpolate(0.0), 10.0);
    EXPECT_DOUBLE_EQ(t.interpolate(0.25), 12.5);
    EXPECT_EQ(t.interpolate(1.0), 20.0); // interior breakpoint
    EXPECT_DOUBLE_EQ(t.interpolate(2.0), 10.0);
    EXPECT_EQ(t.interpolate(3.0), 0.0);
    EXPECT_EQ(t.interpolate(100.0), 0.0);
}

TEST(LookupTable1D, SizeCheckAndMonotonicity)
{
    LookupTable1D t;
    t.getIndexDataRef(0) = {0.0};
    t.getValueDataRef() = {1.0};
    EXPECT_FALSE(t.isDataSizeOK()); // fewer than 2 points
    t.getIndexDataRef(0) = {0.0, 1.0};
    t.getValueDataRef() = {1.0, 2.0, 3.0};
    EXPECT_FALSE(t.isDataSizeOK());
    t.getValueDataRef() = {1.0, 2.0};
    EXPECT_TRUE(t.isDataSizeOK());

    t.getIndexDataRef(0) = {0.0, 1.0, 1.0};
    t.getValueDataRef() = {1.0, 2.0, 3.0};
    EXPECT_EQ(t.getIndexOrder(0), LookupTableND::IndexOrder::NotStrictlyMonotone);
    EXPECT_FALSE(t.isDataOK());
    t.getIndexDataRef(0) = {3.0, 2.0, 1.0};
    EXPECT_EQ(t.getIndexOrder(0), LookupTableND::IndexOrder::StrictlyDecreasing);
}

TEST(LookupTable1D, SortDecreasingAndUnsorted)
{
    LookupTable1D t;
    t.getIndexDataRef(0) = {3.0, 2.0, 1.0, 0.0};
    t.getValueDataRef() = {30.0, 20.0, 10.0, 0.0};
    EXPECT_FALSE(t.isDataOK());
    t.sortIncreasing();
    ASSERT_TRUE(t.isDataOK());
    EXPECT_EQ(t.getIndexDataRef(0), (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
    EXPECT_EQ(t.getValueDataRef(), (std::vector<double>{0.0, 10.0, 20.0, 30.0}));
    EXPECT_DOUBLE_EQ(t.interpolate(2.5), 25.0);

    LookupTable1D u;
    u.getIndexDataRef(0) = {2.0, 0.0, 3.0, 1.0, 5.0, 4.0};
    u.getValueDataRef() = {-2.0, 0.0, -3.0, -1.0, -5.0, -4.0};
    u.sortIncreasing();
    ASSERT_TRUE(u.isDataOK());
    EXPECT_EQ(u.getIndexDataRef(0), (std::vector<double>{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}));
    EXPECT_EQ(u.getValueDataRef(), (std::vector<double>{0.0, -1.0, -2.0, -3.0, -4.0, -5.0}));
}

namespace {
double bilinearF(double r, double c) { return 1.0 + 2.0 * r - 3.0 * c + 0.5 * r * c; }
double trilinearF(double r, double c, double p) { return bilinearF(r, c) + 4.0 * p - r * p + 0.25 * r * c * p; }
} // namespace

TEST(LookupTable2D, BilinearIsExactForBilinearFunctionAndClamps)
{
    LookupTable2D t;
    const std::vector<double> R = {0.0, 1.0, 2.5, 4.0};
    const std::vector<double> C = {-1.0, 0.0, 2.0};
    t.getIndexDataRef(0) = R;
    t.getIndexDataRef(1) = C;
    for (double r : R) {
        for (double c : C) { t.getValueDataRef().push_back(bilinearF(r, c)); }
    }
    ASSERT_TRUE(t.isDataOK());
    for (double r : {0.0, 0.3, 1.0, 2.0, 3.9, 4.0}) {
        for (double c : {-1.0, -0.5, 0.0, 1.7, 2.0}) { EXPECT_NEAR(t.interpolate(r, c), bilinearF(r, c), 1e-12); }
    }
    // Outside the ranges: coordinates are clamped.
    EXPECT_NEAR(t.interpolate(-10.0, 10.0), bilinearF(0.0, 2.0), 1e-12);
    EXPECT_NEAR(t.interpolate(10.0, -10.0), bilinearF(4.0, -1.0), 1e-12);
}

TEST(LookupTable2D, SortMovesValueSlicesWithIndex)
{
    LookupTable2D t;
    const std::vector<double> R = {2.0, 0.0, 1.0};
    const std::vector<double> C = {5.0, 3.0};
    t.getIndexDataRef(0) = R;
    t.getIndexDataRef(1) = C;
    for (double r : R) {
        for (double c : C) { t.getValueDataRef().push_back(bilinearF(r, c)); }
    }
    EXPECT_FALSE(t.isDataOK());
    t.sortIncreasing();
    ASSERT_TRUE(t.isDataOK());
    EXPECT_EQ(t.getIndexDataRef(0), (std::vector<double>{0.0, 1.0, 2.0}));
    EXPECT_EQ(t.getIndexDataRef(1), (std::vector<double>{3.0, 5.0}));
    EXPECT_EQ(t.getValueDataRef()[0], bilinearF(0.0, 3.0));
    EXPECT_EQ(t.getValueDataRef()[1], bilinearF(0.0, 5.0));
    EXPECT_EQ(t.getValueDataRef()[5], bilinearF(2.0, 5.0));
    EXPECT_NEAR(t.interpolate(1.5, 4.0), bilinearF(1.5, 4.0), 1e-12);
}

TEST(LookupTable3D, TrilinearIsExactForTrilinearFunction)
{
    LookupTable3D t;
    const std::vector<double> R = {0.0, 1.0, 3.0};
    const std::vector<double> C = {0.0, 2.0};
    const std::vector<double> P = {-1.0, 0.0, 0.5, 2.0};
    t.getIndexDataRef(0) = R;
    t.getIndexDataRef(1) = C;
    t.getIndexDataRef(2) = P;
    for (double r : R) {
        for (double c : C) {
            for (double p : P) { t.getValueDataRef().push_back(trilinearF(r, c, p)); }
        }
    }
    ASSERT_TRUE(t.isDataOK());
    for (double r : {0.0, 0.5, 2.2, 3.0}) {
        for (double c : {0.0, 1.3, 2.0}) {
            for (double p : {-1.0, -0.2, 0.5, 1.9}) {
                EXPECT_NEAR(t.interpolate(r, c, p), trilinearF(r, c, p), 1e-12);
            }
        }
    }
    EXPECT_NEAR(t.interpolate(5.0, -1.0, 9.0), trilinearF(3.0, 0.0, 2.0), 1e-12);
}

TEST(LookupTable3D, SortWithSliceSwapping)
{
    LookupTable3D t;
    const std::vector<double> R = {1.0, 0.0};
    const std::vector<double> C = {0.0, 2.0};
    const std::vector<double> P = {0.5, -1.0, 2.0};
    t.getIndexDataRef(0) = R;
    t.getIndexDataRef(1) = C;
    t.getIndexDataRef(2) = P;
    for (double r : R) {
        for (double c : C) {
            for (double p : P) { t.getValueDataRef().push_back(trilinearF(r, c, p)); }
        }
    }
    t.sortIncreasing();
    ASSERT_TRUE(t.isDataOK());
    for (double r : {0.0, 0.7}) {
        for (double p : {-1.0, 0.1, 1.5}) { EXPECT_NEAR(t.interpolate(r, 1.0, p), trilinearF(r, 1.0, p), 1e-12); }
    }
}
