#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/numerics/Matrix.h"

using namespace tlmhub;

namespace {
void fill(Matrix& m, const std::vector<std::vector<double>>& v)
{
    for (int i = 0; i < m.rows(); ++i) {
        for (int j = 0; j < m.cols(); ++j) { m[i][j] = v[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]; }
    }
}
} // namespace

TEST(Matrix, SwapRowsSwapsPointers)
{
    Matrix m(2, 2);
    fill(m, {{1, 2}, {3, 4}});
    double* row0 = m[0];
    m.swaprows(0, 1);
    EXPECT_EQ(m[1], row0);
    EXPECT_EQ(m[0][0], 3.0);
    Matrix copy = m;
    EXPECT_EQ(copy[0][1], 4.0);
    EXPECT_NE(copy[0], m[0]);
    Vec v(3);
    v.set(2.5);
    EXPECT_EQ(v[2], 2.5);
    EXPECT_EQ(v.length(), 3);
}

TEST(LU, SolvesKnown3x3SystemThatNeedsPivoting)
{
    // A x = b with x = (1, -2, 3); A[0][0] = 0 forces a row swap.
    const std::vector<std::vector<double>> A = {{0, 2, 1}, {4, 1, -1}, {2, -3, 5}};
    Matrix m(3, 3);
    fill(m, A);
    Vec b(3);
    b[0] = 2 * -2 + 3;               // -1
    b[1] = 4 - 2 - 3;                // -1
    b[2] = 2 + 6 + 15;               // 23
    std::vector<int> order(3);
    ASSERT_TRUE(ludcmp(m, order));
    Vec x(3);
    solvlu(m, b, x, order);
    EXPECT_NEAR(x[0], 1.0, 1e-14);
    EXPECT_NEAR(x[1], -2.0, 1e-14);
    EXPECT_NEAR(x[2], 3.0, 1e-14);
    // Largest |pivot| in column 0 is row 1.
    EXPECT_EQ(order[0], 1);
}

TEST(LU, CroutFormUnitUpperTimesLowerReproducesPermutedA)
{
    const std::vector<std::vector<double>> A = {{2, -1, 0, 3}, {1, 5, 2, -2}, {-4, 1, 7, 1}, {3, 3, -1, 6}};
    Matrix m(4, 4);
    fill(m, A);
    std::vector<int> order(4);
    ASSERT_TRUE(ludcmp(m, order));
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            // L = lower incl. diagonal, U = strict upper + unit diagonal.
            double s = 0.0;
            for (int k = 0; k <= std::min(i, j); ++k) {
                const double l = m[i][k];
                const double u = (k == j) ? 1.0 : m[k][j];
                s += l * u;
            }
            EXPECT_NEAR(s, A[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])][static_cast<std::size_t>(j)], 1e-12);
        }
    }
}

TEST(LU, SingularColumnReportsFailure)
{
    Matrix m(3, 3);
    fill(m, {{1, 2, 3}, {2, 4, 5}, {3, 6, 1}});
    std::vector<int> order(3);
    EXPECT_FALSE(ludcmp(m, order)); // column 1 of L vanishes after elimination
    // Quirk: a singularity that only shows in the last diagonal element is not detected.
    fill(m, {{1, 2, 3}, {2, 4, 6}, {1, 1, 1}});
    EXPECT_TRUE(ludcmp(m, order));
    EXPECT_NEAR(m[2][2], 0.0, 1e-15);
    Matrix z(2, 2);
    fill(z, {{0, 1}, {0, 2}});
    EXPECT_FALSE(ludcmp(z, order));
    Matrix n(2, 2);
    fill(n, {{NAN, 1}, {NAN, 2}});
    EXPECT_FALSE(ludcmp(n, order));
}

TEST(LU, OneAndTwoDimensional)
{
    Matrix m1(1, 1);
    m1[0][0] = 4.0;
    std::vector<int> order(2);
    ASSERT_TRUE(ludcmp(m1, order));
    Vec b1(1), x1(1);
    b1[0] = 2.0;
    solvlu(m1, b1, x1, order);
    EXPECT_EQ(x1[0], 0.5);

    Matrix m2(2, 2);
    fill(m2, {{1, 2}, {3, 4}});
    ASSERT_TRUE(ludcmp(m2, order));
    Vec b2(2), x2(2);
    b2[0] = 5.0;  // x = (1, 2)
    b2[1] = 11.0;
    solvlu(m2, b2, x2, order);
    EXPECT_NEAR(x2[0], 1.0, 1e-15);
    EXPECT_NEAR(x2[1], 2.0, 1e-15);
}
