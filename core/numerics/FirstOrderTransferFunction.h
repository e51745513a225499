// Discrete first-order transfer functions, bilinear (Tustin) discretisation
// (utilities.md §5, §5.1, §5.2).
//   G(s) = (a1*s + a0) / (b1*s + b0),  num = {a0, a1}, den = {b0, b1}
#pragma once

#include <array>

#include "core/numerics/Delay.h"

namespace tlmhub {

class FirstOrderTransferFunction
{
public:
    void initialize(double h, const double num[2], const double den[2], double u0 = 0.0, double y0 = 0.0,
                    double min = -1.5e300, double max = 1.5e300);
    void initialize(double h, const std::array<double, 2>& num, const std::array<double, 2>& den, double u0 = 0.0,
                    double y0 = 0.0, double min = -1.5e300, double max = 1.5e300)
    {
        initialize(h, num.data(), den.data(), u0, y0, min, max);
    }

    void initializeValues(double u0, double y0);
    void setMinMax(double min, double max);

    // Recompute coefficients with the stored step; delayed values are kept.
    void setNum(const double num[2]);
    void setDen(const double den[2]);
    void setNumDen(const double num[2], const double den[2]);
    void setNum(const std::array<double, 2>& num) { setNum(num.data()); }
    void setDen(const std::array<double, 2>& den) { setDen(den.data()); }
    void setNumDen(const std::array<double, 2>& num, const std::array<double, 2>& den)
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
    double delayedY() const { return mDelayedY; }
    bool isSaturated() const { return mIsSaturated; }

protected:
    void computeNum(const double num[2]);
    void computeDen(const double den[2]);

    double mValue = 0.0;
    double mDelayedU = 0.0;
    double mDelayedY = 0.0;
    double mCoeffU[2] = {0.0, 0.0};
    double mCoeffY[2] = {0.0, 0.0};
    double mMin = -1.5e300;
    double mMax = 1.5e300;
    double mTimeStep = 0.0;
    bool mIsSaturated = false;
    Delay mBackupU;
    Delay mBackupY;
};

// G(s) = 1 / (s/wc + 1)
class FirstOrderLowPassFilter : public FirstOrderTransferFunction
{
public:
    void initialize(double h, double wc, double u0 = 0.0, double y0 = 0.0, double min = -1.5e300,
                    double max = 1.5e300);
    double breakFrequency() const;
};

// Time step read through a pointer so it may change between steps. At
// saturation both delayed input and output are forced to the limit
// (anti-windup), and the comparisons are strict.
class FirstOrderTransferFunctionVariable
{
public:
    void initialize(const double* pTimeStep, const double num[2], const double den[2], double u0 = 0.0,
                    double y0 = 0.0, double min = -1.5e300, double max = 1.5e300);
    void initialize(const double* pTimeStep, const std::array<double, 2>& num, const std::array<double, 2>& den,
                    double u0 = 0.0, double y0 = 0.0, double min = -1.5e300, double max = 1.5e300)
    {
        initialize(pTimeStep, num.data(), den.data(), u0, y0, min, max);
    }

    void initializeValues(double u0, double y0);
    void setMinMax(double min, double max);
    void setNum(const double num[2]);
    void setDen(const double den[2]);
    void setNumDen(const double num[2], const double den[2]);

    double update(double u);

    double value() const { return mValue; }
    double delayedU() const { return mDelayedU; }
    double delayedY() const { return mDelayedY; }

private:
    void recomputeCoefficients();

    double mValue = 0.0;
    double mDelayedU = 0.0;
    double mDelayedY = 0.0;
    double mNum[2] = {0.0, 0.0};
    double mDen[2] = {0.0, 0.0};
    double mCoeffU[2] = {0.0, 0.0};
    double mCoeffY[2] = {0.0, 0.0};
    double mMin = -1.5e300;
    double mMax = 1.5e300;
    const double* mpTimeStep = nullptr;
    double mPrevTimeStep = 0.0;
};

} // namespace tlmhub
