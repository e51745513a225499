#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type torsionally elastic gear stage: rotational spring with gear ratio as a TLM
// element with first-order filtered waves. The written wave lags the filter by a step.
class MechanicGearShaft : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPmr1 = nullptr;
    Port* mpPmr2 = nullptr;
    double *mpGearRatio = nullptr, *mpKs = nullptr, *mpAlpha = nullptr;
    // Storage of the plain "alpha" constant; overwritten by alpha#Value in initialize,
    // so the constant never has an effect (kept so old files load the same way).
    double mAlpha = 0.3;
    double mKs = 1000.0;
    double *mpPmr1_w = nullptr, *mpPmr1_c = nullptr, *mpPmr1_Zc = nullptr;
    double *mpPmr2_w = nullptr, *mpPmr2_c = nullptr, *mpPmr2_Zc = nullptr;
    double mCmr1 = 0.0, mCmr2 = 0.0, mCmr1f = 0.0, mCmr2f = 0.0;
};

} // namespace tlmhub
