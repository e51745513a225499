#include <gtest/gtest.h>

#include "core/numerics/DoubleIntegratorWithDamping.h"
#include "core/numerics/DoubleIntegratorWithDampingAndCoulombFriction.h"

using namespace tlmhub;

TEST(DoubleIntegratorWithDamping, UndampedConstantAccelerationIsExact)
{
    const double h = 0.25, a = 2.0;
    DoubleIntegratorWithDamping di;
    di.initialize(h, 0.0, a, 0.0, 0.0);
    for (int k = 1; k <= 40; ++k) {
        di.integrate(a);
        const double t = k * h;
        EXPECT_EQ(di.valueFirst(), a * t);
        EXPECT_EQ(di.valueSecond(), a * t * t / 2.0);
    }
}

TEST(DoubleIntegratorWithDamping, DampedStepMatchesHandComputation)
{
    const double h = 0.1, w0 = 0.2;
    DoubleIntegratorWithDamping di;
    di.initialize(h, w0, 1.0, 3.0, 2.0);
    EXPECT_EQ(di.valueFirst(), 2.0);
    EXPECT_EQ(di.valueSecond(), 3.0);
    di.integrate(5.0);
    const double v = (2.0 - w0) / (2.0 + w0) * 2.0 + h / (2.0 + w0) * (5.0 + 1.0);
    EXPECT_DOUBLE_EQ(di.valueFirst(), v);
    EXPECT_DOUBLE_EQ(di.valueSecond(), 3.0 + h / 2.0 * (v + 2.0));
    // Damping decays velocity with zero input.
    DoubleIntegratorWithDamping d2;
    d2.initialize(h, w0, 0.0, 0.0, 1.0);
    for (int i = 0; i < 100; ++i) { d2.integrate(0.0); }
    EXPECT_LT(d2.valueFirst(), 0.01);
    EXPECT_GT(d2.valueFirst(), 0.0);
}

TEST(DoubleIntegratorWithDamping, RedoRecomputesLastStepFromBackup)
{
    DoubleIntegratorWithDamping a;
    DoubleIntegratorWithDamping b;
    a.initialize(0.01, 0.1, 0.5, 1.0, -2.0);
    b.initialize(0.01, 0.1, 0.5, 1.0, -2.0);
    a.integrate(3.0);
    b.integrate(3.0);
    a.integrateWithUndo(7.0);
    a.redoIntegrate(4.0);
    b.integrate(4.0);
    EXPECT_EQ(a.valueFirst(), b.valueFirst());
    EXPECT_EQ(a.valueSecond(), b.valueSecond());
}

TEST(DoubleIntegratorWithDampingAndCoulombFriction, StickingThenBreakawayThenStop)
{
    const double h = 0.5, Us = 2.0, Uk = 1.0;
    DoubleIntegratorWithDampingAndCoulombFriction di;
    di.initialize(h, 0.0, Us, Uk, 0.0, 0.0, 0.0);
    EXPECT_EQ(di.mode(), 0);

    di.integrate(1.5); // below static friction: nothing happens
    EXPECT_EQ(di.mode(), 0);
    EXPECT_EQ(di.valueFirst(), 0.0);

    di.integrate(3.0); // breaks away, but the state does not move this step
    EXPECT_EQ(di.mode(), 1);
    EXPECT_EQ(di.valueFirst(), 0.0);
    EXPECT_EQ(di.valueSecond(), 0.0);

    di.integrate(3.0); // moves with ue = u - Uk = 2, uPrev = u0 = 0
    EXPECT_EQ(di.valueFirst(), h / 2.0 * (2.0 + 0.0)); // 0.5
    EXPECT_EQ(di.valueSecond(), h / 2.0 * (0.5 + 0.0)); // 0.125

    di.integrate(3.0); // v = 0.5 + 0.25*(2 + 2) = 1.5, x = 0.125 + 0.25*2 = 0.625
    EXPECT_EQ(di.valueFirst(), 1.5);
    EXPECT_EQ(di.valueSecond(), 0.625);

    // Mild braking: ues = -(2/h)*1.5 - 2 = -8 < u - Uk = -6 -> keeps moving.
    DoubleIntegratorWithDampingAndCoulombFriction mild = di;
    mild.integrate(-5.0);
    EXPECT_EQ(mild.mode(), 1);
    EXPECT_EQ(mild.valueFirst(), 1.5 + 0.25 * (-6.0 + 2.0));

    // Strong braking: ues = -8 > u - Uk = -11 -> velocity would cross zero: stop.
    di.integrate(-10.0);
    EXPECT_EQ(di.mode(), 0);
    EXPECT_EQ(di.valueFirst(), 0.0);
    EXPECT_EQ(di.valueSecond(), 0.625);
}

TEST(DoubleIntegratorWithDampingAndCoulombFriction, NegativeDirectionAndHeldStartVelocity)
{
    const double h = 0.5;
    DoubleIntegratorWithDampingAndCoulombFriction di;
    di.initialize(h, 0.0, 2.0, 1.0, 0.0, 1.0, 4.0);
    di.integrate(0.0); // mode 0: start velocity held, not integrated
    EXPECT_EQ(di.valueFirst(), 4.0);
    EXPECT_EQ(di.valueSecond(), 1.0);
    di.integrate(-2.0); // exactly -Us breaks away (inclusive)
    EXPECT_EQ(di.mode(), -1);
    EXPECT_EQ(di.valueFirst(), 4.0);
    // Now moving negative with v = 4: ues = -(2/0.5)*4 - 0 = -16 < u + Uk = -2 -> stop.
    di.integrate(-3.0);
    EXPECT_EQ(di.mode(), 0);
    EXPECT_EQ(di.valueFirst(), 0.0);
    EXPECT_EQ(di.valueSecond(), 1.0);
    // Break away negative and accelerate: ue = -3 + 1 = -2.
    di.integrate(-3.0);
    EXPECT_EQ(di.mode(), -1);
    di.integrate(-3.0);
    EXPECT_EQ(di.valueFirst(), h / 2.0 * (-2.0 + 0.0));
}

TEST(DoubleIntegratorWithDampingAndCoulombFriction, RedoIgnoresFriction)
{
    DoubleIntegratorWithDampingAndCoulombFriction di;
    di.initialize(0.5, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0);
    di.integrateWithUndo(3.0);
    di.redoIntegrate(3.0);
    EXPECT_EQ(di.valueFirst(), 0.25 * 3.0);
    EXPECT_EQ(di.valueSecond(), 0.25 * 0.75);
}
