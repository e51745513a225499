#include "core/numerics/SecondOrderTransferFunction.h"

#include <algorithm>
#include <cstddef>

namespace tlmhub {

namespace {

// Shared Tustin coefficient formulas; h*h is evaluated left to right as a*h*h.
inline void tustin2(const double c[3], double h, double out[3])
{
    out[0] = c[0] * h * h + 2.0 * c[1] * h + 4.0 * c[2];
    out[1] = 2.0 * c[0] * h * h - 8.0 * c[2];
    out[2] = c[0] * h * h - 2.0 * c[1] * h + 4.0 * c[2];
}

} // namespace

// ------------------------------------------------------------ SecondOrderTransferFunction

void SecondOrderTransferFunction::initialize(double h, const double num[3], const double den[3], double u0,
                                             double y0, double min, double max, double sy0)
{
    mIsSaturated = false;
    mMin = min;
    mMax = max;
    mDelayedU = u0;
    mDelayed2U = u0;
    mValue = y0; // not clamped
    mDelayedY = std::max(std::min(y0, mMax), mMin);
    mDelayed2Y = mDelayedY - sy0 * mTimeStep; // uses the step stored by the previous initialize
    mTimeStep = h;
    computeNum(num);
    computeDen(den);
    setBackupLength(1);
}

void SecondOrderTransferFunction::initializeValues(double u0, double y0)
{
    mDelayedU = u0;
    mDelayed2U = u0;
    mDelayedY = y0;
    mDelayed2Y = y0;
    mValue = y0;
}

void SecondOrderTransferFunction::setMinMax(double min, double max)
{
    mMin = min;
    mMax = max;
}

void SecondOrderTransferFunction::computeNum(const double num[3]) { tustin2(num, mTimeStep, mCoeffU); }
void SecondOrderTransferFunction::computeDen(const double den[3]) { tustin2(den, mTimeStep, mCoeffY); }
void SecondOrderTransferFunction::setNum(const double num[3]) { computeNum(num); }
void SecondOrderTransferFunction::setDen(const double den[3]) { computeDen(den); }
void SecondOrderTransferFunction::setNumDen(const double num[3], const double den[3])
{
    computeNum(num);
    computeDen(den);
}

void SecondOrderTransferFunction::setBackupLength(int n)
{
    mBackupU.initialize(2 * n, mDelayedU);
    mBackupY.initialize(2 * n, mDelayedY);
}

void SecondOrderTransferFunction::backup()
{
    mBackupU.update(mDelayed2U);
    mBackupU.update(mDelayedU);
    mBackupY.update(mDelayed2Y);
    mBackupY.update(mDelayedY);
}

void SecondOrderTransferFunction::restoreBackup(int n)
{
    const std::size_t m = static_cast<std::size_t>((n > 0) ? n - 1 : 0);
    mDelayedU = mBackupU.getIdx(2 * m);
    mDelayed2U = mBackupU.getIdx(2 * m + 1);
    mDelayedY = mBackupY.getIdx(2 * m);
    mDelayed2Y = mBackupY.getIdx(2 * m + 1);
}

double SecondOrderTransferFunction::updateWithBackup(double u)
{
    backup();
    return update(u);
}

double SecondOrderTransferFunction::update(double u)
{
    double y = 1.0 / mCoeffY[0]
               * (mCoeffU[0] * u + mCoeffU[1] * mDelayedU + mCoeffU[2] * mDelayed2U - mCoeffY[1] * mDelayedY
                  - mCoeffY[2] * mDelayed2Y);
    if (y >= mMax) {
        y = mMax;
        mIsSaturated = true;
    } else if (y <= mMin) {
        y = mMin;
        mIsSaturated = true;
    } else {
        mIsSaturated = false;
    }
    mDelayed2U = mDelayedU;
    mDelayedU = u;
    mDelayed2Y = mDelayedY;
    mDelayedY = y;
    mValue = y;
    return y;
}

// ------------------------------------------------------------ SecondOrderTransferFunctionVariable

void SecondOrderTransferFunctionVariable::initialize(const double* pTimeStep, const double num[3],
                                                     const double den[3], double u0, double y0, double min,
                                                     double max)
{
    mMin = min;
    mMax = max;
    mDelayedU = u0;
    mDelayed2U = u0;
    mValue = y0;
    mDelayedY = std::max(std::min(y0, mMax), mMin);
    mDelayed2Y = mDelayedY;
    for (int i = 0; i < 3; ++i) {
        mNum[i] = num[i];
        mDen[i] = den[i];
    }
    mpTimeStep = pTimeStep;
    mPrevTimeStep = *pTimeStep;
    recomputeCoefficients();
}

void SecondOrderTransferFunctionVariable::initializeValues(double u0, double y0)
{
    mDelayedU = u0;
    mDelayed2U = u0;
    mDelayedY = y0;
    mDelayed2Y = y0;
}

void SecondOrderTransferFunctionVariable::setMinMax(double min, double max)
{
    mMin = min;
    mMax = max;
}

void SecondOrderTransferFunctionVariable::setNum(const double num[3])
{
    for (int i = 0; i < 3; ++i) { mNum[i] = num[i]; }
    recomputeCoefficients();
}

void SecondOrderTransferFunctionVariable::setDen(const double den[3])
{
    for (int i = 0; i < 3; ++i) { mDen[i] = den[i]; }
    recomputeCoefficients();
}

void SecondOrderTransferFunctionVariable::setNumDen(const double num[3], const double den[3])
{
    for (int i = 0; i < 3; ++i) {
        mNum[i] = num[i];
        mDen[i] = den[i];
    }
    recomputeCoefficients();
}

void SecondOrderTransferFunctionVariable::recomputeCoefficients()
{
    tustin2(mNum, *mpTimeStep, mCoeffU);
    tustin2(mDen, *mpTimeStep, mCoeffY);
}

double SecondOrderTransferFunctionVariable::update(double u)
{
    if (mPrevTimeStep != *mpTimeStep) {
        mPrevTimeStep = *mpTimeStep;
        recomputeCoefficients();
    }
    // Note the grouping of the output terms differs from the fixed-step class.
    double y = 1.0 / mCoeffY[0]
               * (mCoeffU[0] * u + mCoeffU[1] * mDelayedU + mCoeffU[2] * mDelayed2U
                  - (mCoeffY[1] * mDelayedY + mCoeffY[2] * mDelayed2Y));
    if (y > mMax) {
        mDelayedU = mMax;
        mDelayed2U = mMax;
        mDelayedY = mMax;
        mDelayed2Y = mMax;
        y = mMax;
    } else if (y < mMin) {
        mDelayedU = mMin;
        mDelayed2U = mMin;
        mDelayedY = mMin;
        mDelayed2Y = mMin;
        y = mMin;
    } else {
        mDelayed2U = mDelayedU;
        mDelayedU = u;
        mDelayed2Y = mDelayedY;
        mDelayedY = y;
    }
    mValue = y;
    return y;
}

} // namespace tlmhub
