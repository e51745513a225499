#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

using namespace tlmhub;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
}

TEST(AuxiliarySimulationFunctions, PiHasCDigits)
{
    EXPECT_EQ(pi, 3.14159265358979323846);
    EXPECT_EQ(pi, std::acos(-1.0));
}

TEST(AuxiliarySimulationFunctions, LimitClampsAndToleratesSwappedBounds)
{
    EXPECT_EQ(limit(5.0, 1.0, 3.0), 3.0);
    EXPECT_EQ(limit(-5.0, 1.0, 3.0), 1.0);
    EXPECT_EQ(limit(2.0, 1.0, 3.0), 2.0);
    // Reversed bounds are swapped first.
    EXPECT_EQ(limit(5.0, 3.0, 1.0), 3.0);
    EXPECT_EQ(limit(-5.0, 3.0, 1.0), 1.0);
    EXPECT_EQ(limit(2.0, 3.0, 1.0), 2.0);
    // NaN passes through.
    EXPECT_TRUE(std::isnan(limit(kNaN, 0.0, 1.0)));
    EXPECT_EQ(limit2(7.0, -100.0, 0.0, 1.0), 1.0);

    double v = 10.0;
    limitValue(v, 4.0, -4.0);
    EXPECT_EQ(v, 4.0);
}

TEST(AuxiliarySimulationFunctions, LowAndUpperLimits)
{
    EXPECT_EQ(lowLimit(-1.0, 0.5), 0.5);
    EXPECT_EQ(lowLimit(1.0, 0.5), 1.0);
    EXPECT_EQ(lowerLimit(-1.0, 0.5), 0.5);
    EXPECT_EQ(upperLimit(2.0, 0.5), 0.5);
    EXPECT_EQ(upperLimit(0.2, 0.5), 0.2);
}

TEST(AuxiliarySimulationFunctions, DxLimitGatesUseOneEMinusNine)
{
    EXPECT_EQ(dxLimit(0.5, 0.0, 1.0), 1.0);
    EXPECT_EQ(dxLimit(1.0, 0.0, 1.0), 1e-9); // inclusive
    EXPECT_EQ(dxLimit(0.0, 0.0, 1.0), 1e-9);
    // Bounds are NOT swapped here: with xmax < x the gate closes.
    EXPECT_EQ(dxLimit(0.5, 1.0, 0.0), 1e-9);

    EXPECT_EQ(dxLimit2(1.0, 1.0, 0.0, 1.0), 1e-9);
    EXPECT_EQ(dxLimit2(1.0, 0.0, 0.0, 1.0), 1e-9); // sx == 0 at the limit
    EXPECT_EQ(dxLimit2(1.0, -1.0, 0.0, 1.0), 1.0); // pointing back inside
    EXPECT_EQ(dxLimit2(0.0, 1.0, 0.0, 1.0), 1.0);
    EXPECT_EQ(dxLimit2(0.0, -1.0, 0.0, 1.0), 1e-9);

    EXPECT_EQ(dxLimit3(5.0, 1.0, 0.0, 1.0), 0.0);
    EXPECT_EQ(dxLimit3(-5.0, 1.0, 0.0, 1.0), -5.0);
    EXPECT_EQ(dxLimit3(-5.0, 0.0, 0.0, 1.0), 0.0);
    EXPECT_EQ(dxLimit3(5.0, 0.5, 0.0, 1.0), 5.0);
    EXPECT_EQ(dxLimit3(kNaN, 1.0, 0.0, 1.0), 0.0); // fmin semantics

    EXPECT_EQ(dxLowLimit(0.0, 0.0), 1e-9);
    EXPECT_EQ(dxLowLimit(0.1, 0.0), 1.0);
    EXPECT_EQ(dxLowLimit2(0.0, 0.0, 0.0), 1e-9);
    EXPECT_EQ(dxLowLimit2(0.0, 1.0, 0.0), 1.0);
}

TEST(AuxiliarySimulationFunctions, SignAndSwitchQuirks)
{
    EXPECT_EQ(sign(0.0), 1.0);
    EXPECT_EQ(sign(-0.0), 1.0);
    EXPECT_EQ(sign(-3.0), -1.0);
    EXPECT_EQ(sign(kNaN), -1.0);

    EXPECT_EQ(ifPositive(0.0, 1.0, 2.0), 1.0);
    EXPECT_EQ(ifPositive(-1e-300, 1.0, 2.0), 2.0);
    EXPECT_EQ(ifElse(false, 1.0, 2.0), 2.0);
    EXPECT_EQ(dtIfPositive(0.0, 1.0, 2.0), 1.0);
    EXPECT_EQ(dfIfPositive(0.0, 1.0, 2.0), 1.0); // both 1 at zero
    EXPECT_EQ(dfIfPositive(1.0, 1.0, 2.0), 0.0);

    EXPECT_EQ(onPositive(0.0), 0.0);
    EXPECT_EQ(onNegative(0.0), 1.0);
    EXPECT_EQ(onPositive(2.0), 1.0);
    EXPECT_EQ(onNegative(2.0), 0.0);
    EXPECT_EQ(dxOnPositive(1.0), 0.0);
    EXPECT_EQ(dxOnNegative(-1.0), 0.0);

    EXPECT_EQ(dxAbs(0.0), 1.0);
    EXPECT_EQ(dxAbs(-2.0), -1.0);
    EXPECT_TRUE(doubleToBool(0.51));
    EXPECT_FALSE(doubleToBool(0.5));
    EXPECT_EQ(boolToDouble(true), 1.0);

    EXPECT_TRUE(equalSignsBool(0.0, 5.0));
    EXPECT_FALSE(equalSignsBool(0.0, -5.0));
    EXPECT_EQ(equalSigns(-1.0, -2.0), 1.0);
    EXPECT_EQ(greaterThan(1.0, 1.0), 0.0);
    EXPECT_EQ(greaterThanOrEqual(1.0, 1.0), 1.0);
}

TEST(AuxiliarySimulationFunctions, NonZero)
{
    const double L = 10.0 * DBL_MIN;
    EXPECT_EQ(nonZero(0.0), L);
    EXPECT_EQ(nonZero(-0.0), L); // -0.0 >= 0.0
    EXPECT_EQ(nonZero(1e-308), L);
    EXPECT_EQ(nonZero(-1e-308), -L);
    EXPECT_EQ(nonZero(-1.0), -1.0);
    EXPECT_EQ(nonZero(L), L);
}

TEST(AuxiliarySimulationFunctions, FuzzyEqual)
{
    EXPECT_TRUE(fuzzyEqual(1.0, 1.0 + 1e-6));
    EXPECT_FALSE(fuzzyEqual(1.0, 1.0001));
    EXPECT_TRUE(fuzzyEqual(0.0, 1e-22)); // E = 1e-5 * 2.22e-16
    EXPECT_FALSE(fuzzyEqual(0.0, 1e-20));
    EXPECT_TRUE(fuzzyEqual(INFINITY, INFINITY));
    EXPECT_TRUE(fuzzyEqual(0.0, -0.0));
    EXPECT_TRUE(fuzzyEqual(100.0, 100.01, 1e-4));
}

TEST(AuxiliarySimulationFunctions, SignedSquareL)
{
    // Far from zero it tends to sign(x)*sqrt(|x|).
    EXPECT_NEAR(signedSquareL(1e6, 1.0), 1000.0, 1e-6);
    EXPECT_NEAR(signedSquareL(-1e6, 1.0), -1000.0, 1e-6);
    // Near zero it is approximately x/sqrt(x0).
    EXPECT_NEAR(signedSquareL(1e-6, 4.0), 1e-6 / 2.0, 1e-15);
    EXPECT_EQ(signedSquareL(0.0, 1.0), 0.0);
    EXPECT_TRUE(std::isnan(signedSquareL(0.0, 0.0)));
    // Odd function.
    EXPECT_EQ(signedSquareL(-2.5, 0.3), -signedSquareL(2.5, 0.3));

    // The derivative matches a central difference.
    for (double x : {-3.0, -0.2, 0.05, 1.0, 7.0}) {
        const double h = 1e-6;
        const double num = (signedSquareL(x + h, 0.5) - signedSquareL(x - h, 0.5)) / (2 * h);
        EXPECT_NEAR(dxSignedSquareL(x, 0.5), num, 1e-6) << "x=" << x;
    }
}

TEST(AuxiliarySimulationFunctions, SquareAbsL)
{
    EXPECT_EQ(squareAbsL(0.0, 4.0), 0.0);
    EXPECT_DOUBLE_EQ(squareAbsL(5.0, 4.0), 1.0);
    EXPECT_DOUBLE_EQ(squareAbsL(-5.0, 4.0), 1.0); // not signed
    EXPECT_DOUBLE_EQ(dxSquareAbsL(5.0, 4.0), 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(dxSquareAbsL(-5.0, 4.0), -1.0 / 6.0);
}

TEST(AuxiliarySimulationFunctions, AtanAndArcSin)
{
    EXPECT_EQ(Atan2L(0.0, 0.0), 0.0);
    EXPECT_EQ(Atan2L(1.0, 1.0), std::atan2(1.0, 1.0));
    EXPECT_DOUBLE_EQ(d1Atan2L(1.0, 2.0), 2.0 / 5.001);
    EXPECT_DOUBLE_EQ(d2Atan2L(1.0, 2.0), -1.0 / 5.001);

    EXPECT_EQ(ArcSinL(2.0), std::asin(0.9999999999));
    EXPECT_EQ(ArcSinL(-2.0), std::asin(-0.9999999999));
    EXPECT_DOUBLE_EQ(ArcSinL(0.5), pi / 6.0);
    EXPECT_TRUE(std::isfinite(dxArcSinL(1.0)));
    EXPECT_DOUBLE_EQ(dxArcSinL(0.0), 1.0);
}

TEST(AuxiliarySimulationFunctions, DiffAngle)
{
    EXPECT_NEAR(diffAngle(0.1, 2.0 * pi - 0.1), 0.2, 1e-12);
    EXPECT_NEAR(diffAngle(2.0 * pi - 0.1, 0.1), -0.2, 1e-12);
    EXPECT_EQ(diffAngle(0.3, 0.1), 0.3 - 0.1);
    // Tie |d0| == |d2|: the shifted value is chosen.
    EXPECT_EQ(diffAngle(pi, 0.0), pi - 0.0 - 2.0 * pi);
    // Only one 2*pi correction: 4*pi becomes 2*pi, not 0.
    EXPECT_NEAR(diffAngle(4.0 * pi, 0.0), 2.0 * pi, 1e-12);
}

TEST(AuxiliarySimulationFunctions, Segare)
{
    const double d = 0.01;
    EXPECT_EQ(segare(0.0, d), 0.0);
    EXPECT_NEAR(segare(d, d), pi * d * d / 4.0, 1e-18);
    EXPECT_NEAR(segare(d / 2.0, d), pi * d * d / 8.0, 1e-18);
    EXPECT_EQ(segare(-1.0, d), segare(0.0, d));
    EXPECT_EQ(segare(2.0 * d, d), segare(d, d));
    EXPECT_EQ(dxSegare(-1.0, d), 0.0);
    EXPECT_EQ(dxSegare(1.0, d), 0.0);
    const double x = 0.3 * d;
    const double h = 1e-9;
    EXPECT_NEAR(dxSegare(x, d), (segare(x + h, d) - segare(x - h, d)) / (2 * h), 1e-9);
}

TEST(AuxiliarySimulationFunctions, AerodynamicCoefficients)
{
    const double ap = 0.3, an = 0.3, aw = 0.02;
    // Attached flow around zero: CLift ~ alpha*CLalpha.
    EXPECT_EQ(CLift(0.0, 5.0, ap, an, aw, aw), 0.0);
    EXPECT_NEAR(CLift(0.05, 5.0, ap, an, aw, aw), 0.25, 1e-9);
    // Deep stall: CLift ~ 0.707107*sin(2 alpha).
    EXPECT_NEAR(CLift(1.0, 5.0, ap, an, aw, aw), 0.707107 * std::sin(2.0), 1e-9);
    EXPECT_NEAR(CDragInd(0.05, 8.0, 0.9, 5.0, ap, an, aw, aw), 0.31831 * 0.0025 * 25.0 / (8.0 * 0.9), 1e-9);
    EXPECT_NEAR(CDragInd(1.0, 8.0, 0.9, 5.0, ap, an, aw, aw), std::sin(1.0) * std::sin(1.0), 1e-9);
    EXPECT_NEAR(CMoment(0.0, 0.1, 0.5, ap, an, aw, aw), 0.1, 1e-9);
    EXPECT_NEAR(CMoment(-1.0, 0.1, 0.5, ap, an, aw, aw), -0.5, 1e-9);
    // Exactly at the stall angle the blend is 50/50 (Sp = 1/2).
    const double Sn = 1.0 / (1.0 + std::pow(2.71828, -2.0 * (-ap - an) / aw));
    EXPECT_NEAR(CMoment(ap, 0.0, 1.0, ap, an, aw, aw), 0.5 + Sn, 1e-12);
}

TEST(AuxiliarySimulationFunctions, IntegerLikeHelpers)
{
    EXPECT_EQ(tlmhub::div(7.0, 2.0), 3.0);
    EXPECT_EQ(tlmhub::div(-7.0, 2.0), -3.0); // truncation toward zero
    EXPECT_EQ(rem(-7.0, 2.0), -1.0);
    EXPECT_EQ(rem(7.5, 2.0), 1.5);
    EXPECT_EQ(tlmhub::mod(7.0, 3.0), 1.0);
    EXPECT_EQ(tlmhub::mod(6.6, 3.0), 1.0);   // 6.6 rounds to 7
    EXPECT_EQ(tlmhub::mod(-8.0, 3.0), -1.0); // int(-7.5) = -7, -7 % 3 = -1 (C semantics)
    EXPECT_EQ(tlmhub::mod(-7.0, 3.0), 0.0);  // int(-6.5) = -6
}

TEST(AuxiliarySimulationFunctions, AngleConversion)
{
    EXPECT_NEAR(deg2rad(180.0), pi, 1e-15);
    EXPECT_NEAR(rad2deg(pi / 2.0), 90.0, 1e-12);
    EXPECT_EQ(deg2rad(1.0), pi / 180.0);
}

TEST(MathematicaWrappers, Definitions)
{
    EXPECT_EQ(Power(2.0, 10.0), 1024.0);
    EXPECT_NEAR(Cot(pi / 4.0), 1.0, 1e-15);
    EXPECT_NEAR(Csc(pi / 2.0), 1.0, 1e-15);
    EXPECT_NEAR(Sec(pi / 3.0), 2.0, 1e-14);
    EXPECT_EQ(SecL(0.3), Sec(0.3));
    EXPECT_NEAR(DxSecL(pi / 4.0), std::sqrt(2.0), 1e-14);
    EXPECT_TRUE(std::isnan(Sqrt(-1.0)));
    EXPECT_EQ(Abs(-2.5), 2.5);
    EXPECT_EQ(Sin(0.3), std::sin(0.3));
    EXPECT_EQ(Cos(0.3), std::cos(0.3));
    EXPECT_EQ(Tan(0.3), std::tan(0.3));
}
