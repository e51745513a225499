#include <gtest/gtest.h>

#include <cmath>

#include "core/numerics/EquationSystemSolver.h"

using namespace tlmhub;

namespace {
// Linear residual F = A x - b with A = [[3, 1], [1, 2]], b = (9, 8) -> x* = (2, 3).
void assemble(Matrix& J, Vec& F, const Vec& x)
{
    J[0][0] = 3.0;
    J[0][1] = 1.0;
    J[1][0] = 1.0;
    J[1][1] = 2.0;
    F[0] = 3.0 * x[0] + x[1] - 9.0;
    F[1] = x[0] + 2.0 * x[1] - 8.0;
}
} // namespace

TEST(EquationSystemSolver, WeightsPerIteration)
{
    const double expectedWeights[5] = {1.0, 0.67, 0.5, 0.5, 0.5};
    for (int iter = 1; iter <= 5; ++iter) {
        EquationSystemSolver s(2);
        Matrix J(2, 2);
        Vec F(2), x(2);
        x[0] = 0.0;
        x[1] = 0.0;
        assemble(J, F, x);
        ASSERT_TRUE(s.solve(J, F, x, iter));
        // Full Newton step would land on (2, 3); damped step is w times that.
        const double w = expectedWeights[iter - 1];
        EXPECT_NEAR(x[0], w * 2.0, 1e-14) << "iter " << iter;
        EXPECT_NEAR(x[1], w * 3.0, 1e-14) << "iter " << iter;
    }
}

TEST(EquationSystemSolver, TwoIterationPatternOfGeneratedComponents)
{
    EquationSystemSolver s(2);
    Matrix J(2, 2);
    Vec F(2), x(2);
    x[0] = 10.0;
    x[1] = -4.0;
    for (int iter = 1; iter <= 2; ++iter) {
        assemble(J, F, x); // refill every element; J is permuted by the LU
        ASSERT_TRUE(s.solve(J, F, x, iter));
    }
    // Linear system: exact after the full first step; the second changes nothing.
    EXPECT_NEAR(x[0], 2.0, 1e-13);
    EXPECT_NEAR(x[1], 3.0, 1e-13);
}

TEST(EquationSystemSolver, NonlinearNewtonConverges)
{
    // F = (x0^2 - 2, x0*x1 - 1): root (sqrt 2, 1/sqrt 2).
    EquationSystemSolver s(2);
    Matrix J(2, 2);
    Vec F(2), x(2);
    x[0] = 1.0;
    x[1] = 1.0;
    for (int k = 0; k < 30; ++k) {
        J[0][0] = 2.0 * x[0];
        J[0][1] = 0.0;
        J[1][0] = x[1];
        J[1][1] = x[0];
        F[0] = x[0] * x[0] - 2.0;
        F[1] = x[0] * x[1] - 1.0;
        ASSERT_TRUE(s.solve(J, F, x));
    }
    EXPECT_NEAR(x[0], std::sqrt(2.0), 1e-14);
    EXPECT_NEAR(x[1], 1.0 / std::sqrt(2.0), 1e-14);
}

TEST(EquationSystemSolver, SingularJacobianReturnsFalse)
{
    EquationSystemSolver s(2);
    Matrix J(2, 2);
    Vec F(2), x(2);
    J[0][0] = 0.0;
    J[0][1] = 1.0;
    J[1][0] = 0.0;
    J[1][1] = 2.0;
    F[0] = 1.0;
    F[1] = 1.0;
    x[0] = 0.0;
    x[1] = 0.0;
    EXPECT_FALSE(s.solve(J, F, x, 1));
}
