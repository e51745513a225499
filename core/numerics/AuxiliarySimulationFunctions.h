// Scalar auxiliary functions used by component equations (utilities.md §1, §2).
// All functions are pure and inline because they are called in per-step loops.
// Floating-point expressions are written in the evaluation order given by the
// specification so that results reproduce Hopsan bit for bit.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>

namespace tlmhub {

inline constexpr double pi = 3.14159265358979323846;

// ---------------------------------------------------------------- limits (§2.1-2.2)

// Clamp in place; reversed bounds are swapped first. NaN passes through.
inline void limitValue(double& rValue, double min, double max)
{
    if (min > max) {
        const double tmp = min;
        min = max;
        max = tmp;
    }
    if (rValue > max) {
        rValue = max;
    } else if (rValue < min) {
        rValue = min;
    }
}

inline double limit(double x, double xmin, double xmax)
{
    double y = x;
    limitValue(y, xmin, xmax);
    return y;
}

// The direction argument is ignored (kept for generated-code compatibility).
inline double limit2(double x, double /*sx*/, double xmin, double xmax)
{
    return limit(x, xmin, xmax);
}

inline double lowLimit(double x, double xmin) { return (x < xmin) ? xmin : x; }
inline double lowerLimit(double value, double lim) { return (value < lim) ? lim : value; }
inline double upperLimit(double value, double lim) { return (value > lim) ? lim : value; }

// ---------------------------------------------------------------- derivative gates (§2.3)
// The "closed" factor is 1e-9 rather than 0 so Jacobians stay non-singular.

inline double dxLimit(double x, double xmin, double xmax)
{
    if (x >= xmax) { return 0.000000001; }
    if (x <= xmin) { return 0.000000001; }
    return 1.0;
}

inline double dxLimit2(double x, double sx, double xmin, double xmax)
{
    if (x >= xmax && sx >= 0.0) { return 0.000000001; }
    if (x <= xmin && sx <= 0.0) { return 0.000000001; }
    return 1.0;
}

// Returns a limited derivative (not a factor); fmin/fmax give 0 for NaN dx.
inline double dxLimit3(double dx, double x, double xmin, double xmax)
{
    if (x >= xmax) { return std::fmin(dx, 0.0); }
    if (x <= xmin) { return std::fmax(dx, 0.0); }
    return dx;
}

inline double dxLowLimit(double x, double xmin)
{
    return (x <= xmin) ? 0.000000001 : 1.0;
}

inline double dxLowLimit2(double x, double sx, double xmin)
{
    return (x <= xmin && sx <= 0.0) ? 0.000000001 : 1.0;
}

// ---------------------------------------------------------------- sign and switches (§2.4)

// sign(0) == +1 and sign(NaN) == -1, by design of the reference.
inline double sign(double x) { return (x >= 0.0) ? 1.0 : -1.0; }

inline double ifElse(bool cond, double y1, double y2) { return cond ? y1 : y2; }
inline double ifPositive(double x, double y1, double y2) { return (x >= 0.0) ? y1 : y2; }
inline double dtIfPositive(double x, double /*y1*/, double /*y2*/) { return (x >= 0.0) ? 1.0 : 0.0; }
inline double dfIfPositive(double x, double /*y1*/, double /*y2*/) { return (x <= 0.0) ? 1.0 : 0.0; }

inline double onPositive(double x) { return (x <= 0.0) ? 0.0 : 1.0; }
inline double onNegative(double x) { return (x <= 0.0) ? 1.0 : 0.0; }
inline double dxOnPositive(double /*x*/) { return 0.0; }
inline double dxOnNegative(double /*x*/) { return 0.0; }

inline double dxAbs(double x) { return (x < 0.0) ? -1.0 : 1.0; }

inline bool doubleToBool(double v) { return v > 0.5; }
inline double boolToDouble(bool b) { return b ? 1.0 : 0.0; }

inline bool equalSignsBool(double x, double y)
{
    return (x < 0.0 && y < 0.0) || (x >= 0.0 && y >= 0.0);
}
inline double equalSigns(double x, double y) { return equalSignsBool(x, y) ? 1.0 : 0.0; }

inline double greaterThan(double x, double y) { return (x > y) ? 1.0 : 0.0; }
inline double greaterThanOrEqual(double x, double y) { return (x >= y) ? 1.0 : 0.0; }

// ---------------------------------------------------------------- nonZero, fuzzyEqual (§2.5-2.6)

// Keeps a divisor away from exact zero; -0.0 maps to +L because -0.0 >= 0.0.
inline double nonZero(double x)
{
    const double L = 10.0 * DBL_MIN;
    if (x >= 0.0 && x < L) { return L; }
    if (x > -L && x < 0.0) { return -L; }
    return x;
}

inline bool fuzzyEqual(double x, double y, double eps = 1e-5)
{
    const double E = eps * std::numeric_limits<double>::epsilon();
    const double d = std::fabs(x - y);
    if (x == y) { return true; }
    if (x == 0.0 || y == 0.0 || d < E) { return d < E; }
    return d / (std::fabs(x) + std::fabs(y)) < eps;
}

// ---------------------------------------------------------------- regularised roots (§2.7-2.8)

inline double signedSquareL(double x, double x0)
{
    return std::fabs(x) * std::pow(1.0 / (std::pow(x0, 2.0) + std::pow(std::fabs(x), 2.0)), 0.25) * sign(x);
}

inline double dxSignedSquareL(double x, double x0)
{
    return std::pow(1.0 / (std::pow(x0, 2.0) + std::pow(std::fabs(x), 2.0)), 1.25)
           * (2.0 * std::pow(x0, 2.0) + std::pow(std::fabs(x), 2.0)) * dxAbs(x) * sign(x) / 2.0;
}

inline double squareAbsL(double x, double x0)
{
    return -std::sqrt(x0) + std::sqrt(x0 + std::fabs(x));
}

inline double dxSquareAbsL(double x, double x0)
{
    return 1.0 / (std::sqrt(x0 + std::fabs(x)) * 2.0) * sign(x);
}

// ---------------------------------------------------------------- angles (§2.9-2.11, §2.15)

inline double Atan2L(double y, double x)
{
    if (x == 0.0 && y == 0.0) { return 0.0; }
    return std::atan2(y, x);
}

inline double d1Atan2L(double y, double x) { return x / (0.001 + x * x + y * y); }
inline double d2Atan2L(double y, double x) { return -y / (0.001 + x * x + y * y); }

inline double ArcSinL(double x)
{
    return std::asin(limit(x, -0.9999999999, 0.9999999999));
}

inline double dxArcSinL(double x)
{
    const double xl = limit(x, -0.9999999999, 0.9999999999);
    return 1.0 / std::sqrt(1.0 - std::pow(xl, 2.0));
}

// Single +-2pi correction; both tests compare with |d0|, the second one wins.
inline double diffAngle(double fi1, double fi2)
{
    const double d0 = fi1 - fi2;
    const double d1 = fi1 - fi2 + 2.0 * pi;
    const double d2 = fi1 - fi2 - 2.0 * pi;
    double out = d0;
    if (std::fabs(d0) >= std::fabs(d1)) { out = d1; }
    if (std::fabs(d0) >= std::fabs(d2)) { out = d2; }
    return out;
}

inline double deg2rad(double d) { return (pi / 180.0) * d; }
inline double rad2deg(double r) { return (180.0 / pi) * r; }

// ---------------------------------------------------------------- circular segment (§2.12)

inline double segare(double x, double d)
{
    double x1;
    if (x < 0.0) {
        x1 = 0.0;
    } else if (x > d) {
        x1 = d;
    } else {
        x1 = x;
    }
    return -(d * (2.0 * (d - 2.0 * x1) * std::sqrt((d - x1) * x1 / (d * d)) - d * std::acos(1.0 - 2.0 * x1 / d))) / 4.0;
}

inline double dxSegare(double x, double d)
{
    double x1;
    if (x < 0.0) {
        x1 = 0.0;
    } else if (x > d) {
        x1 = d;
    } else {
        x1 = x;
    }
    return 2.0 * std::sqrt((d - x1) * x1);
}

// ---------------------------------------------------------------- aerodynamics (§2.13)
// The blending uses the literal 2.71828 (not exp) like the reference.

namespace detail {
inline double aeroSn(double alpha, double an, double awn)
{
    return 1.0 / (1.0 + std::pow(2.71828, -2.0 * (-alpha - an) / awn));
}
inline double aeroSp(double alpha, double ap, double awp)
{
    return 1.0 / (1.0 + std::pow(2.71828, -2.0 * (alpha - ap) / awp));
}
} // namespace detail

inline double CLift(double alpha, double CLalpha, double ap, double an, double awp, double awn)
{
    const double Sn = detail::aeroSn(alpha, an, awn);
    const double Sp = detail::aeroSp(alpha, ap, awp);
    const double A = 1.0 - Sn - Sp;
    const double B = Sn + Sp;
    return A * alpha * CLalpha + 0.707107 * B * std::sin(2.0 * alpha);
}

inline double CDragInd(double alpha, double AR, double e, double CLalpha, double ap, double an, double awp,
                       double awn)
{
    const double Sn = detail::aeroSn(alpha, an, awn);
    const double Sp = detail::aeroSp(alpha, ap, awp);
    const double A = 1.0 - Sn - Sp;
    const double B = Sn + Sp;
    return 0.31831 * A * std::pow(alpha, 2.0) * std::pow(CLalpha, 2.0) / (AR * e) + B * std::pow(std::sin(alpha), 2.0);
}

inline double CMoment(double alpha, double Cm0, double Cmfs, double ap, double an, double awp, double awn)
{
    const double Sn = detail::aeroSn(alpha, an, awn);
    const double Sp = detail::aeroSp(alpha, ap, awp);
    const double A = 1.0 - Sn - Sp;
    const double B = Sn + Sp;
    return A * Cm0 + B * Cmfs * sign(alpha);
}

// ---------------------------------------------------------------- integer-like (§2.14)

// Truncation toward zero (Modelica div).
inline double div(double x, double y)
{
    const double q = x / y;
    return (q > 0.0) ? std::floor(q) : std::ceil(q);
}

inline double rem(double x, double y) { return x - div(x, y) * y; }

// Arguments rounded with int(v + 0.5) (asymmetric for negatives, as in the
// reference); C '%' keeps the dividend's sign. y rounding to 0 is undefined in
// the reference; here it returns NaN instead of trapping.
inline double mod(double x, double y)
{
    const int ix = static_cast<int>(x + 0.5);
    const int iy = static_cast<int>(y + 0.5);
    if (iy == 0) { return std::numeric_limits<double>::quiet_NaN(); }
    return static_cast<double>(ix % iy);
}

} // namespace tlmhub
