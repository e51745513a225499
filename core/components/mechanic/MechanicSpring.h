#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type translational spring with free length x0, filtered waves (damping alpha) and
// a drift correction that pulls the mean port force towards the position-based force.
class MechanicSpring : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPm1 = nullptr, *mpPm2 = nullptr;
    double *mpKs = nullptr, *mpX0 = nullptr, *mpEps = nullptr, *mpAlpha = nullptr;
    double *mpF1 = nullptr, *mpX1 = nullptr, *mpV1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr;
    double *mpF2 = nullptr, *mpX2 = nullptr, *mpV2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr;
    double mCm1 = 0.0, mCm2 = 0.0, mCm1f = 0.0, mCm2f = 0.0;
};

} // namespace tlmhub
