// Discrete second-order transfer functions, bilinear (Tustin) discretisation
// (utilities.md §6, §6.1).
//   G(s) = (a2*s^2 + a1*s + a0) / (b2*s^2 + b1*s + b0)
//   num = {a0, a1, a2}, den = {b0, b1, b2}
#pragma once

#include <array>

#include "core/numerics/Delay.h"

namespace tlmhub {

class SecondOrderTransferFunction
{
public:
    // Note: y[k-2] is seeded as y1 - sy0*h_stored where h_stored is the step of
    // the PREVIOUS initialize (0 for a fresh object). This reproduces the
    // reference exactly; do not "fix" it (see utilities.md §6).
    void initialize(double h, const double num[3], const double den[3], double u0 = 0.0, double y0 = 0.0,
                    double min = -1.5e300, double max = 1.5e300, double sy0 = 0.0);
    void initialize(double h, const std::array<double, 3>& num, const std::array<double, 3>& den, double u0 = 0.0,
                    double y0 = 0.0, double min = -1.5e300, double max = 1.5e300, double sy0 = 0.0)
    {
        initialize(h, num.data(), den.data(), u0, y0, min, max, sy0);
    }

    void initializeValues(double u0, double y0);
    void setMinMax(double min, double max);

    void setNum(const double num[3]);
    void setDen(const double den[3]);
    void setNumDen(const double num[3], const double den[3]);
    void setNum(const std::array<double, 3>& num) { setNum(num.data()); }
    void setDen(const std::array<double, 3>& den) { setDen(den.data()); }
    void setNumDen(const std::array<double, 3>& num, const std::array<double, 3>& den)
    {
        setNumDen(num.data(), den.data());
    }

    void setBackupLength(int n);
    void backup();
    void restoreBackup(int n = 1);
    double updateWithBackup(double u);

    double update(double u);

    double value() const { return mValue; }
    double delayedU() const { return mDelayedU; }
    double delayed2U() const { return mDelayed2U; }
    double delayedY() const { return mDelayedY; }
    double delayed2Y() const { return mDelayed2Y; }
    bool isSaturated() const { return mIsSaturated; }

private:
    void computeNum(const double num[3]);
    void computeDen(const double den[3]);

    double mValue = 0.0;
    double mDelayedU = 0.0;
    double mDelayed2U = 0.0;
    double mDelayedY = 0.0;
    double mDelayed2Y = 0.0;
    double mCoeffU[3] = {0.0, 0.0, 0.0};
    double mCoeffY[3] = {0.0, 0.0, 0.0};
    double mMin = -1.5e300;
    double mMax = 1.5e300;
    double mTimeStep = 0.0; // must start at 0, see initialize()
    bool mIsSaturated = false;
    Delay mBackupU;
    Delay mBackupY;
};

// Time step read through a pointer; strict limit comparisons, and at
// saturation all four delayed values are forced to the limit.
class SecondOrderTransferFunctionVariable
{
public:
    void initialize(const double* pTimeStep, const double num[3], const double den[3], double u0 = 0.0,
                    double y0 = 0.0, double min = -1.5e300, double max = 1.5e300);
    void initialize(const double* pTimeStep, const std::array<double, 3>& num, const std::array<double, 3>& den,
                    double u0 = 0.0, double y0 = 0.0, double min = -1.5e300, double max = 1.5e300)
    {
        initialize(pTimeStep, num.data(), den.data(), u0, y0, min, max);
    }

    // Does not touch value() (reference behaviour).
    void initializeValues(double u0, double y0);
    void setMinMax(double min, double max);
    void setNum(const double num[3]);
    void setDen(const double den[3]);
    void setNumDen(const double num[3], const double den[3]);

    double update(double u);

    double value() const { return mValue; }
    double delayedU() const { return mDelayedU; }
    double delayed2U() const { return mDelayed2U; }
    double delayedY() const { return mDelayedY; }
    double delayed2Y() const { return mDelayed2Y; }

private:
    void recomputeCoefficients();

    double mValue = 0.0;
    double mDelayedU = 0.0;
    double mDelayed2U = 0.0;
    double mDelayedY = 0.0;
    double mDelayed2Y = 0.0;
    double mNum[3] = {0.0, 0.0, 0.0};
    double mDen[3] = {0.0, 0.0, 0.0};
    double mCoeffU[3] = {0.0, 0.0, 0.0};
    double mCoeffY[3] = {0.0, 0.0, 0.0};
    double mMin = -1.5e300;
    double mMax = 1.5e300;
    const double* mpTimeStep = nullptr;
    double mPrevTimeStep = 0.0;
};

} // namespace tlmhub
