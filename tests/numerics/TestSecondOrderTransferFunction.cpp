#include <gtest/gtest.h>

#include <cmath>

#include "core/numerics/SecondOrderTransferFunction.h"

using namespace tlmhub;

TEST(SecondOrderTransferFunction, FirstStepMatchesHandComputedTustin)
{
    // num = {1, 0, 0}, den = {1, 1, 1}, h = 1:
    // cu = {1, 2, 1}; cy = {1+2+4, 2-8, 1-2+4} = {7, -6, 3}
    SecondOrderTransferFunction tf;
    tf.initialize(1.0, {1.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 1.0, 2.0);
    EXPECT_EQ(tf.value(), 2.0);
    const double y = tf.update(3.0);
    EXPECT_DOUBLE_EQ(y, (1.0 * 3.0 + 2.0 * 1.0 + 1.0 * 1.0 + 6.0 * 2.0 - 3.0 * 2.0) / 7.0);
    EXPECT_EQ(tf.delayedU(), 3.0);
    EXPECT_EQ(tf.delayed2U(), 1.0);
    EXPECT_EQ(tf.delayedY(), y);
    EXPECT_EQ(tf.delayed2Y(), 2.0);
}

TEST(SecondOrderTransferFunction, StepResponseMatchesAnalytic)
{
    // Step applied at the first update (u0 = 0): the trapezoidal rule sees the
    // input ramp over the first step, i.e. an effective delay of h/2. With that
    // shift the error is O((w*h)^2) (measured ~1.2e-7 here).
    const double w = 10.0, z = 0.5, h = 1e-4;
    SecondOrderTransferFunction tf;
    tf.initialize(h, {1.0, 0.0, 0.0}, {1.0, 2.0 * z / w, 1.0 / (w * w)}, 0.0, 0.0);
    const double wd = w * std::sqrt(1.0 - z * z);
    double maxErr = 0.0;
    for (int k = 1; k <= 20000; ++k) {
        const double t = k * h - h / 2.0;
        const double exact = 1.0 - std::exp(-z * w * t) / std::sqrt(1.0 - z * z) * std::sin(wd * t + std::acos(z));
        maxErr = std::fmax(maxErr, std::fabs(tf.update(1.0) - exact));
    }
    EXPECT_LT(maxErr, 1e-6);
}

TEST(SecondOrderTransferFunction, InitialDerivativeUsesPreviouslyStoredStep)
{
    SecondOrderTransferFunction tf;
    // Fresh object: stored step is 0, so sy0 has no effect.
    tf.initialize(0.01, {1.0, 0.0, 0.0}, {1.0, 0.1, 0.01}, 0.0, 1.5, -1.5e300, 1.5e300, 5.0);
    EXPECT_EQ(tf.delayedY(), 1.5);
    EXPECT_EQ(tf.delayed2Y(), 1.5);
    // Second initialisation of the same instance uses the previous h (0.01),
    // not the new one (0.02).
    tf.initialize(0.02, {1.0, 0.0, 0.0}, {1.0, 0.1, 0.01}, 0.0, 1.5, -1.5e300, 1.5e300, 5.0);
    EXPECT_EQ(tf.delayed2Y(), 1.5 - 5.0 * 0.01);
}

TEST(SecondOrderTransferFunction, SaturationInclusiveAndClampedOutputStored)
{
    // G = 1, h = 1: cu = cy = {1, 2, 1}: y = u + 2u1 + u2 - 2y1 - y2.
    SecondOrderTransferFunction tf;
    tf.initialize(1.0, {1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0.0, 0.0, -1.0, 1.0);
    EXPECT_EQ(tf.update(1.0), 1.0); // exactly at max
    EXPECT_TRUE(tf.isSaturated());
    EXPECT_EQ(tf.update(5.0), 1.0); // 5 + 2 - 2 = 5 -> 1
    EXPECT_TRUE(tf.isSaturated());
    EXPECT_EQ(tf.delayedU(), 5.0);
    EXPECT_EQ(tf.delayed2U(), 1.0);
    EXPECT_EQ(tf.delayedY(), 1.0);
    EXPECT_EQ(tf.delayed2Y(), 1.0);
    EXPECT_EQ(tf.update(-6.0), 1.0); // -6 + 10 + 1 - 2 - 1 = 2 -> 1
    EXPECT_TRUE(tf.isSaturated());
    EXPECT_EQ(tf.update(-4.0), -1.0); // -4 - 12 + 5 - 2 - 1 = -14 -> -1
    EXPECT_TRUE(tf.isSaturated());
}

TEST(SecondOrderTransferFunction, BackupAndRestore)
{
    SecondOrderTransferFunction tf;
    tf.initialize(0.1, {1.0, 0.0, 0.0}, {1.0, 0.3, 0.02});
    tf.update(1.0);
    tf.update(2.0);
    const double u1 = tf.delayedU(), u2 = tf.delayed2U(), y1 = tf.delayedY(), y2 = tf.delayed2Y();
    tf.updateWithBackup(3.0);
    tf.restoreBackup();
    EXPECT_EQ(tf.delayedU(), u1);
    EXPECT_EQ(tf.delayed2U(), u2);
    EXPECT_EQ(tf.delayedY(), y1);
    EXPECT_EQ(tf.delayed2Y(), y2);

    tf.setBackupLength(2);
    tf.updateWithBackup(4.0);
    tf.updateWithBackup(5.0);
    tf.restoreBackup(2);
    EXPECT_EQ(tf.delayedU(), u1);
    EXPECT_EQ(tf.delayed2U(), u2);
    EXPECT_EQ(tf.delayedY(), y1);
    EXPECT_EQ(tf.delayed2Y(), y2);
}

TEST(SecondOrderTransferFunction, InitializeValuesAndSetDen)
{
    SecondOrderTransferFunction tf;
    tf.initialize(1.0, {1.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
    tf.initializeValues(2.0, 3.0);
    EXPECT_EQ(tf.value(), 3.0);
    EXPECT_EQ(tf.delayed2U(), 2.0);
    EXPECT_EQ(tf.delayed2Y(), 3.0);
    tf.setDen({2.0, 0.0, 0.0}); // cy = {2, 4, 2}: y = (u + 2u1 + u2 - 4y1 - 2y2)/2
    EXPECT_EQ(tf.update(1.0), (1.0 + 4.0 + 2.0 - 12.0 - 6.0) / 2.0);
}

TEST(SecondOrderTransferFunctionVariable, MatchesFixedWhenUnsaturated)
{
    double h = 0.001;
    SecondOrderTransferFunctionVariable var;
    SecondOrderTransferFunction fixed;
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 0.02, 0.0001};
    var.initialize(&h, num, den);
    fixed.initialize(h, num, den);
    for (int i = 0; i < 500; ++i) {
        const double u = std::sin(0.01 * i);
        // The output terms are grouped differently, so only near-equality.
        EXPECT_NEAR(var.update(u), fixed.update(u), 1e-12);
    }
}

TEST(SecondOrderTransferFunctionVariable, SaturationForcesAllDelayedValues)
{
    double h = 1.0;
    SecondOrderTransferFunctionVariable tf;
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 0.0, 0.0};
    tf.initialize(&h, num, den, 0.0, 0.0, -1.0, 1.0);
    EXPECT_EQ(tf.update(1.0), 1.0); // exactly at the limit: normal branch
    EXPECT_EQ(tf.delayedU(), 1.0);
    EXPECT_EQ(tf.delayed2U(), 0.0);
    EXPECT_EQ(tf.update(5.0), 1.0);
    EXPECT_EQ(tf.delayedU(), 1.0);
    EXPECT_EQ(tf.delayed2U(), 1.0);
    EXPECT_EQ(tf.delayedY(), 1.0);
    EXPECT_EQ(tf.delayed2Y(), 1.0);
    // initializeValues does not touch value().
    tf.initializeValues(0.0, 0.5);
    EXPECT_EQ(tf.value(), 1.0);
    EXPECT_EQ(tf.delayed2Y(), 0.5);
}
