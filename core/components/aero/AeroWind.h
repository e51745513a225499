#pragma once
#include "core/Component.h"

namespace tlmhub {

// Wind over a boundary layer with Dryden turbulence: a mean wind growing with altitude
// plus three filtered noise components (along-wind, lateral, vertical) whose intensity
// and length scales depend on the (low-pass filtered) altitude.
class AeroWind : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    // Mean wind speed, turbulence intensities and scale lengths at the filtered altitude.
    void updateLocalScales();
    // The parts of the discretised filters known from earlier steps.
    void computeDelayedParts();

    double *mpV = nullptr, *mpH = nullptr, *mpNoiseU = nullptr, *mpNoiseV = nullptr, *mpNoiseW = nullptr;
    double *mpU0 = nullptr, *mpHeading = nullptr, *mpH0 = nullptr, *mpAlpha = nullptr, *mpAu = nullptr,
           *mpAw = nullptr, *mpWh = nullptr;
    double *mpDu = nullptr, *mpDv = nullptr, *mpUw = nullptr, *mpVw = nullptr, *mpWw = nullptr, *mpHf = nullptr;

    double mU0 = 0.0, mHeading = 0.0, mH0 = 0.0, mAlpha = 0.0, mWh = 0.0, mAw = 0.0;
    double mHf = 0.0, mDu = 0.0, mDv = 0.0, mWw = 0.0;
    double mUw = 0.0, mSu = 0.0, mSv = 0.0, mSw = 0.0, mLu = 0.0, mLv = 0.0, mLw = 0.0, mVe = 0.0;
    // First-order filters: one delayed part. Second-order ones: the part from the last step
    // and the one from the step before (pending = computed last step, used next step).
    double mDelayHf = 0.0, mDelayDu = 0.0;
    double mDelayDv1 = 0.0, mDelayDv2 = 0.0, mPendingDv2 = 0.0;
    double mDelayWw1 = 0.0, mDelayWw2 = 0.0, mPendingWw2 = 0.0;
};

} // namespace tlmhub
