#include "core/numerics/FirstOrderTransferFunction.h"

#include <algorithm>

namespace tlmhub {

// ------------------------------------------------------------ FirstOrderTransferFunction

void FirstOrderTransferFunction::initialize(double h, const double num[2], const double den[2], double u0,
                                            double y0, double min, double max)
{
    mIsSaturated = false;
    mMin = min;
    mMax = max;
    mValue = y0; // deliberately not clamped (reference behaviour)
    mDelayedU = u0;
    mDelayedY = std::max(std::min(y0, mMax), mMin);
    mTimeStep = h;
    computeNum(num);
    computeDen(den);
    setBackupLength(1);
}

void FirstOrderTransferFunction::initializeValues(double u0, double y0)
{
    mDelayedU = u0;
    mDelayedY = y0;
    mValue = y0;
}

void FirstOrderTransferFunction::setMinMax(double min, double max)
{
    mMin = min;
    mMax = max;
}

void FirstOrderTransferFunction::computeNum(const double num[2])
{
    mCoeffU[0] = num[0] * mTimeStep - 2.0 * num[1];
    mCoeffU[1] = num[0] * mTimeStep + 2.0 * num[1];
}

void FirstOrderTransferFunction::computeDen(const double den[2])
{
    mCoeffY[0] = den[0] * mTimeStep - 2.0 * den[1];
    mCoeffY[1] = den[0] * mTimeStep + 2.0 * den[1];
}

void FirstOrderTransferFunction::setNum(const double num[2]) { computeNum(num); }
void FirstOrderTransferFunction::setDen(const double den[2]) { computeDen(den); }
void FirstOrderTransferFunction::setNumDen(const double num[2], const double den[2])
{
    computeNum(num);
    computeDen(den);
}

void FirstOrderTransferFunction::setBackupLength(int n)
{
    mBackupU.initialize(n, mDelayedU);
    mBackupY.initialize(n, mDelayedY);
}

void FirstOrderTransferFunction::backup()
{
    mBackupU.update(mDelayedU);
    mBackupY.update(mDelayedY);
}

void FirstOrderTransferFunction::restoreBackup(int n)
{
    const int m = (n > 0) ? n - 1 : 0;
    mDelayedU = mBackupU.getIdx(static_cast<std::size_t>(m));
    mDelayedY = mBackupY.getIdx(static_cast<std::size_t>(m));
}

double FirstOrderTransferFunction::updateWithBackup(double u)
{
    backup();
    return update(u);
}

double FirstOrderTransferFunction::update(double u)
{
    double y = 1.0 / mCoeffY[1] * (mCoeffU[1] * u + mCoeffU[0] * mDelayedU - mCoeffY[0] * mDelayedY);
    if (y >= mMax) {
        y = mMax;
        mIsSaturated = true;
    } else if (y <= mMin) {
        y = mMin;
        mIsSaturated = true;
    } else {
        mIsSaturated = false;
    }
    mDelayedY = y;
    mDelayedU = u; // the actual input, even when saturated
    mValue = y;
    return y;
}

// ------------------------------------------------------------ FirstOrderLowPassFilter

void FirstOrderLowPassFilter::initialize(double h, double wc, double u0, double y0, double min, double max)
{
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 1.0 / wc};
    FirstOrderTransferFunction::initialize(h, num, den, u0, y0, min, max);
}

double FirstOrderLowPassFilter::breakFrequency() const { return 4.0 / (mCoeffY[1] - mCoeffY[0]); }

// ------------------------------------------------------------ FirstOrderTransferFunctionVariable

void FirstOrderTransferFunctionVariable::initialize(const double* pTimeStep, const double num[2],
                                                    const double den[2], double u0, double y0, double min,
                                                    double max)
{
    mMin = min;
    mMax = max;
    mValue = y0;
    mDelayedU = u0;
    mDelayedY = std::max(std::min(y0, mMax), mMin);
    mNum[0] = num[0];
    mNum[1] = num[1];
    mDen[0] = den[0];
    mDen[1] = den[1];
    mpTimeStep = pTimeStep;
    mPrevTimeStep = *pTimeStep;
    recomputeCoefficients();
}

void FirstOrderTransferFunctionVariable::initializeValues(double u0, double y0)
{
    mDelayedU = u0;
    mDelayedY = y0;
    mValue = y0;
}

void FirstOrderTransferFunctionVariable::setMinMax(double min, double max)
{
    mMin = min;
    mMax = max;
}

void FirstOrderTransferFunctionVariable::setNum(const double num[2])
{
    mNum[0] = num[0];
    mNum[1] = num[1];
    recomputeCoefficients();
}

void FirstOrderTransferFunctionVariable::setDen(const double den[2])
{
    mDen[0] = den[0];
    mDen[1] = den[1];
    recomputeCoefficients();
}

void FirstOrderTransferFunctionVariable::setNumDen(const double num[2], const double den[2])
{
    mNum[0] = num[0];
    mNum[1] = num[1];
    mDen[0] = den[0];
    mDen[1] = den[1];
    recomputeCoefficients();
}

void FirstOrderTransferFunctionVariable::recomputeCoefficients()
{
    const double h = *mpTimeStep;
    mCoeffU[0] = mNum[0] * h - 2.0 * mNum[1];
    mCoeffU[1] = mNum[0] * h + 2.0 * mNum[1];
    mCoeffY[0] = mDen[0] * h - 2.0 * mDen[1];
    mCoeffY[1] = mDen[0] * h + 2.0 * mDen[1];
}

double FirstOrderTransferFunctionVariable::update(double u)
{
    if (*mpTimeStep != mPrevTimeStep) {
        mPrevTimeStep = *mpTimeStep;
        recomputeCoefficients();
    }
    double y = 1.0 / mCoeffY[1] * (mCoeffU[1] * u + mCoeffU[0] * mDelayedU - mCoeffY[0] * mDelayedY);
    if (y > mMax) {
        mDelayedU = mMax;
        mDelayedY = mMax;
        y = mMax;
    } else if (y < mMin) {
        mDelayedU = mMin;
        mDelayedY = mMin;
        y = mMin;
    } else {
        mDelayedY = y;
        mDelayedU = u;
    }
    mValue = y;
    return y;
}

} // namespace tlmhub
