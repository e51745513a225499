#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type on/off 2/2 valve: open = turbulent orifice both ways, checked = check
// valve P1 -> P2 with a cracking pressure.
class Hydraulic22DirectionalCheckValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mpIn = nullptr, *mpKvOpen = nullptr, *mpKvCheck = nullptr, *mpFs = nullptr, *mpOut = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mTurb;
};

} // namespace tlmhub
