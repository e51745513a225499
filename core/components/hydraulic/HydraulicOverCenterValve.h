#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"
#include "core/numerics/ValveHysteresis.h"

namespace tlmhub {

// Q-type over-centre (load holding) valve: restrictor P1 -> P2 opened by
// p1 + a_ratio*p_control against p_ref, with hysteresis and first-order spool.
class HydraulicOverCenterValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPC = nullptr;
    double *mpPref = nullptr, *mpPh = nullptr, *mpAratio = nullptr, *mpXv = nullptr;
    double mTao = 0.01, mKcs = 1e-8, mKcf = 1e-8, mQnom = 0.001, mPnom = 7e6;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpPC_p = nullptr, *mpPC_c = nullptr;
    double mPrevX0 = 0.0, mCs = 0.0, mCf = 0.0, mX0max = 0.0;
    FirstOrderTransferFunction mFilter;
    TurbulentFlowFunction mTurb;
    ValveHysteresis mHyst;
};

} // namespace tlmhub
