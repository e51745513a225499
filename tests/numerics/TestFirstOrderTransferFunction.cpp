#include <gtest/gtest.h>

#include <cmath>

#include "core/numerics/FirstOrderTransferFunction.h"

using namespace tlmhub;

TEST(FirstOrderTransferFunction, FirstStepMatchesHandComputedTustin)
{
    // G = (1*s + 2)/(3*s + 1), h = 0.5:
    // cu0 = 2*0.5 - 2 = -1, cu1 = 3, cy0 = 0.5 - 6 = -5.5, cy1 = 6.5
    FirstOrderTransferFunction tf;
    const double num[2] = {2.0, 1.0};
    const double den[2] = {1.0, 3.0};
    tf.initialize(0.5, num, den, 1.0, 2.0);
    EXPECT_EQ(tf.value(), 2.0);
    const double y = tf.update(4.0);
    EXPECT_DOUBLE_EQ(y, (3.0 * 4.0 - 1.0 * 1.0 + 5.5 * 2.0) / 6.5);
    EXPECT_EQ(tf.value(), y);
    EXPECT_EQ(tf.delayedU(), 4.0);
    EXPECT_EQ(tf.delayedY(), y);
    EXPECT_FALSE(tf.isSaturated());
}

TEST(FirstOrderTransferFunction, ArrayOverloadEqualsPointerOverload)
{
    FirstOrderTransferFunction a;
    FirstOrderTransferFunction b;
    const double num[2] = {2.0, 0.1};
    const double den[2] = {1.0, 0.3};
    a.initialize(0.001, num, den);
    b.initialize(0.001, {2.0, 0.1}, {1.0, 0.3});
    for (int i = 0; i < 50; ++i) {
        const double u = std::sin(0.1 * i);
        EXPECT_EQ(a.update(u), b.update(u));
    }
}

TEST(FirstOrderTransferFunction, ValueBeforeUpdateIsUnclampedY0)
{
    FirstOrderTransferFunction tf;
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 0.0};
    tf.initialize(1.0, num, den, 0.0, 5.0, -3.0, 3.0);
    EXPECT_EQ(tf.value(), 5.0);
    EXPECT_EQ(tf.delayedY(), 3.0);
}

TEST(FirstOrderTransferFunction, SaturationIsInclusiveAndKeepsActualInput)
{
    // G = 1 with h = 1: y = u + uPrev - yPrev.
    FirstOrderTransferFunction tf;
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 0.0};
    tf.initialize(1.0, num, den, 0.0, 0.0, -2.0, 2.0);
    EXPECT_EQ(tf.update(2.0), 2.0); // exactly at max
    EXPECT_TRUE(tf.isSaturated());
    EXPECT_EQ(tf.update(10.0), 2.0); // 10 + 2 - 2 = 10 -> clamped
    EXPECT_TRUE(tf.isSaturated());
    EXPECT_EQ(tf.delayedU(), 10.0); // the actual, unclamped input
    EXPECT_EQ(tf.delayedY(), 2.0);
    EXPECT_EQ(tf.update(-9.0), -1.0); // -9 + 10 - 2
    EXPECT_FALSE(tf.isSaturated());
    EXPECT_EQ(tf.update(-3.0), -2.0); // -3 - 9 + 1 = -11 -> min
    EXPECT_TRUE(tf.isSaturated());
}

TEST(FirstOrderLowPassFilter, StepResponseMatchesAnalytic)
{
    // Input already 1 at t = 0 (u0 = 1) so Tustin sees a true step; the
    // remaining error is O((wc*h)^2).
    const double wc = 10.0;
    const double h = 1e-4;
    FirstOrderLowPassFilter f;
    f.initialize(h, wc, 1.0, 0.0);
    EXPECT_NEAR(f.breakFrequency(), wc, 1e-9);
    double maxErr = 0.0;
    for (int k = 1; k <= 10000; ++k) {
        const double y = f.update(1.0);
        const double t = k * h;
        maxErr = std::fmax(maxErr, std::fabs(y - (1.0 - std::exp(-t * wc))));
    }
    EXPECT_LT(maxErr, 1e-6);
}

TEST(FirstOrderLowPassFilter, CoefficientsAsSpecified)
{
    const double h = 0.01, wc = 3.0;
    FirstOrderLowPassFilter f;
    f.initialize(h, wc, 0.5, 0.25);
    const double y = f.update(1.0);
    EXPECT_EQ(y, (1.0 / (h + 2.0 / wc)) * (h * 1.0 + h * 0.5 - (h - 2.0 / wc) * 0.25));
}

TEST(FirstOrderTransferFunction, SetNumKeepsDelayedValues)
{
    FirstOrderTransferFunction tf;
    tf.initialize(1.0, {1.0, 0.0}, {1.0, 0.0});
    tf.update(3.0);
    const double u1 = tf.delayedU();
    const double y1 = tf.delayedY();
    tf.setNum({2.0, 0.0}); // G = 2: cu = 2h, cy = h -> y = 2u + 2uPrev - yPrev
    EXPECT_EQ(tf.delayedU(), u1);
    EXPECT_EQ(tf.delayedY(), y1);
    EXPECT_EQ(tf.update(1.0), 2.0 * 1.0 + 2.0 * u1 - y1);
}

TEST(FirstOrderTransferFunction, BackupAndRestore)
{
    FirstOrderTransferFunction tf;
    tf.initialize(0.1, {1.0, 0.0}, {1.0, 0.5});
    tf.update(1.0);
    const double u1 = tf.delayedU(), y1 = tf.delayedY();
    tf.updateWithBackup(2.0);
    EXPECT_NE(tf.delayedY(), y1);
    tf.restoreBackup();
    EXPECT_EQ(tf.delayedU(), u1);
    EXPECT_EQ(tf.delayedY(), y1);

    // Longer backup: restore from two backups ago.
    tf.setBackupLength(3);
    const double uA = tf.delayedU(), yA = tf.delayedY();
    tf.updateWithBackup(3.0);
    tf.updateWithBackup(4.0);
    tf.restoreBackup(2);
    EXPECT_EQ(tf.delayedU(), uA);
    EXPECT_EQ(tf.delayedY(), yA);
    tf.restoreBackup(0); // treated as 1
    EXPECT_EQ(tf.delayedU(), 3.0);
}

TEST(FirstOrderTransferFunctionVariable, StrictLimitsAndAntiWindup)
{
    double h = 1.0;
    FirstOrderTransferFunctionVariable tf;
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 0.0};
    tf.initialize(&h, num, den, 0.0, 0.0, -2.0, 2.0);
    EXPECT_EQ(tf.update(2.0), 2.0); // exactly at max: the normal branch
    EXPECT_EQ(tf.delayedU(), 2.0);
    EXPECT_EQ(tf.update(10.0), 2.0); // above: input memory forced to the limit
    EXPECT_EQ(tf.delayedU(), 2.0);
    EXPECT_EQ(tf.delayedY(), 2.0);
    EXPECT_EQ(tf.update(-1.0), -1.0 + 2.0 - 2.0);
}

TEST(FirstOrderTransferFunctionVariable, FollowsTimeStepChanges)
{
    double h = 0.01;
    FirstOrderTransferFunctionVariable var;
    FirstOrderTransferFunction fixedA;
    FirstOrderTransferFunction fixedB;
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 0.2};
    var.initialize(&h, num, den, 0.0, 0.0);
    fixedA.initialize(0.01, num, den);
    for (int i = 0; i < 5; ++i) { EXPECT_EQ(var.update(1.0), fixedA.update(1.0)); }
    h = 0.02;
    fixedB.initialize(0.02, num, den, fixedA.delayedU(), fixedA.delayedY());
    for (int i = 0; i < 5; ++i) { EXPECT_EQ(var.update(1.0), fixedB.update(1.0)); }
}
