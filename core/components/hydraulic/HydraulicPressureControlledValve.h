#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"
#include "core/numerics/ValveHysteresis.h"

namespace tlmhub {

// Q-type pilot-operated valve P1 -> P2: opens when the pilot pressure at P_OPEN exceeds
// the pilot pressure at P_CLOSE plus p_ref. The pilot ports take no flow.
class HydraulicPressureControlledValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPOpen = nullptr, *mpPClose = nullptr;
    double *mpPref = nullptr, *mpPh = nullptr, *mpX0 = nullptr;
    double mTao = 0.01, mKcs = 1e-8, mKcf = 1e-8, mQnom = 0.001, mPnom = 7e6;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpPOpen_p = nullptr, *mpPOpen_c = nullptr, *mpPClose_p = nullptr, *mpPClose_c = nullptr;

    double mCs = 0.0, mCf = 0.0, mPrevX0 = 0.0;
    FirstOrderTransferFunction mFilter;
    TurbulentFlowFunction mTurb;
    ValveHysteresis mHyst;
};

} // namespace tlmhub
