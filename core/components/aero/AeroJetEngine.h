#pragma once
#include "core/Component.h"

namespace tlmhub {

// Jet engine: thrust and fuel flow from throttle and air data, first-order shaft lag.
class AeroJetEngine : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void explicitPart();

    double *mpUin = nullptr, *mpRho = nullptr, *mpT = nullptr, *mpP0 = nullptr, *mpVsound = nullptr,
           *mpSpeed = nullptr, *mpThrustmax = nullptr, *mpSFC0 = nullptr, *mpThau = nullptr, *mpCtm = nullptr,
           *mpCsfct = nullptr, *mpCsfcm = nullptr, *mpE = nullptr;
    double *mpThrust = nullptr, *mpShspeed = nullptr, *mpQmfuel = nullptr;
    double mThrustmax = 0.0, mThau = 0.0, mE = 0.0;
    double mThrust = 0.0, mShspeed = 0.0, mQmfuel = 0.0, mShspeedref = 0.0, mSFC = 0.0, mDelayed1 = 0.0;
};

} // namespace tlmhub
