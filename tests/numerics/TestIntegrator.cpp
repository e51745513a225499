#include <gtest/gtest.h>

#include "core/numerics/Integrator.h"
#include "core/numerics/IntegratorLimited.h"

using namespace tlmhub;

TEST(Integrator, ConstantInputGivesExactlyUTimesT)
{
    // Dyadic step and input so every operation is exact.
    const double h = 0.25, u = 2.0;
    Integrator in;
    in.initialize(h, u, 0.0);
    EXPECT_EQ(in.value(), 0.0);
    for (int k = 1; k <= 400; ++k) { EXPECT_EQ(in.update(u), u * (k * h)); }
}

TEST(Integrator, FirstStepUsesU0AndTrapezoidIsExactForRamps)
{
    Integrator in;
    in.initialize(0.5, 3.0, 1.0);
    EXPECT_EQ(in.update(5.0), 1.0 + 0.5 / 2.0 * (5.0 + 3.0));

    // u = t, y = t^2/2 is reproduced exactly by the trapezoidal rule.
    const double h = 0.125;
    Integrator ramp;
    ramp.initialize(h, 0.0, 0.0);
    for (int k = 1; k <= 64; ++k) {
        const double t = k * h;
        EXPECT_EQ(ramp.update(t), t * t / 2.0);
    }
    ramp.initializeValues(0.0, 7.0);
    EXPECT_EQ(ramp.value(), 7.0);
}

TEST(IntegratorWithBackup, RestoreBackupUndoesUpdate)
{
    IntegratorWithBackup in;
    in.initialize(0.1, 0.0, 0.0);
    in.update(1.0);
    const double y1 = in.value();
    const double u1 = in.delayedU();
    in.updateWithBackup(5.0);
    EXPECT_NE(in.value(), y1);
    in.restoreBackup();
    EXPECT_EQ(in.value(), y1);
    EXPECT_EQ(in.delayedU(), u1);
    // Redo with another input: same as a plain integrator from that state.
    Integrator ref;
    ref.initialize(0.1, u1, y1);
    EXPECT_EQ(in.update(2.0), ref.update(2.0));
}

TEST(IntegratorLimited, ClampsInitialValueAndZeroesInputMemoryAtLimit)
{
    IntegratorLimited in;
    in.initialize(1.0, 0.0, 5.0, -1.0, 1.0);
    EXPECT_EQ(in.value(), 1.0); // y0 clamped

    in.initialize(1.0, 0.0, 0.0, -1.0, 1.0);
    EXPECT_EQ(in.update(1.0), 0.5);  // 0 + 0.5*(1 + 0)
    EXPECT_EQ(in.update(1.0), 1.0);  // 0.5 + 0.5*2 = 1.5 -> 1
    EXPECT_EQ(in.delayedU(), 0.0);   // memory zeroed at the limit
    EXPECT_EQ(in.update(-1.0), 0.5); // 1 + 0.5*(-1 + 0): leaves the limit at once
    EXPECT_EQ(in.delayedU(), -1.0);
}

TEST(IntegratorLimited, StrictComparisonAtExactLimit)
{
    IntegratorLimited in;
    in.initialize(1.0, 0.0, 0.0, -1.0, 1.0);
    EXPECT_EQ(in.update(2.0), 1.0); // exactly max: normal branch keeps u
    EXPECT_EQ(in.delayedU(), 2.0);
    in.setMinMax(-10.0, 10.0);
    EXPECT_EQ(in.value(), 1.0); // state untouched
    EXPECT_EQ(in.update(-4.0), 0.0); // 1 + 0.5*(-4 + 2)
    in.initialize(1.0, 0.0, 0.0, -1.0, 1.0);
    EXPECT_EQ(in.update(-3.0), -1.0); // -1.5 -> min
    EXPECT_EQ(in.delayedU(), 0.0);
}
