#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"
#include "core/numerics/ValveHysteresis.h"

namespace tlmhub {

// Q-type pressure relief valve P1 -> P2 with hysteresis and a first-order spool
// whose break frequency adapts to the line impedances.
class HydraulicPressureReliefValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mpXv = nullptr, *mpPmax = nullptr, *mpTao = nullptr, *mpPh = nullptr;
    double mKcs = 1e-8, mKcf = 1e-8, mQnom = 0.001;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;

    double mPnom = 7e6;
    double mX0max = 0.0, mCs = 0.0, mCf = 0.0, mPrevX0 = 0.0;
    FirstOrderTransferFunction mFilter;
    TurbulentFlowFunction mTurb;
    ValveHysteresis mHyst;
};

} // namespace tlmhub
