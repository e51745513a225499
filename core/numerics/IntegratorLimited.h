// Trapezoidal integrator with output limits and anti-windup (utilities.md §8).
#pragma once

#include <algorithm>

namespace tlmhub {

class IntegratorLimited
{
public:
    void initialize(double h, double u0 = 0.0, double y0 = 0.0, double min = -1.5e300, double max = 1.5e300)
    {
        mTimeStep = h;
        mMin = min;
        mMax = max;
        mDelayedU = u0;
        mDelayedY = std::max(std::min(y0, mMax), mMin);
    }

    void initializeValues(double u0, double y0)
    {
        mDelayedU = u0;
        mDelayedY = y0;
    }

    void setMinMax(double min, double max)
    {
        mMin = min;
        mMax = max;
    }

    double update(double u)
    {
        const double y = mDelayedY + mTimeStep / 2.0 * (u + mDelayedU);
        if (y > mMax) {
            mDelayedY = mMax;
            mDelayedU = 0.0; // forget the input so leaving the limit is not delayed
        } else if (y < mMin) {
            mDelayedY = mMin;
            mDelayedU = 0.0;
        } else {
            mDelayedY = y;
            mDelayedU = u;
        }
        return mDelayedY;
    }

    double value() const { return mDelayedY; }
    double delayedU() const { return mDelayedU; }

private:
    double mDelayedU = 0.0;
    double mDelayedY = 0.0;
    double mMin = -1.5e300;
    double mMax = 1.5e300;
    double mTimeStep = 0.0;
};

} // namespace tlmhub
