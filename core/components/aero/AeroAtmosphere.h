#pragma once
#include "core/Component.h"

namespace tlmhub {

// Standard atmosphere: troposphere with linear lapse rate, isothermal stratosphere.
class AeroAtmosphere : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double *mpHa = nullptr, *mpG0 = nullptr, *mpRhos = nullptr, *mpA = nullptr, *mpR = nullptr, *mpGamma = nullptr,
           *mpTs = nullptr, *mpP0s = nullptr, *mpHtp = nullptr, *mpTtp = nullptr, *mpPtp = nullptr,
           *mpRhotp = nullptr, *mpE = nullptr;
    double *mpRhoa = nullptr, *mpTa = nullptr, *mpP0 = nullptr, *mpVsound = nullptr;
    double mG0 = 0.0, mRhos = 0.0, mA = 0.0, mR = 0.0, mGamma = 0.0, mTs = 0.0, mP0s = 0.0, mHtp = 0.0, mTtp = 0.0,
           mPtp = 0.0, mRhotp = 0.0, mE = 0.0;
};

} // namespace tlmhub
