#pragma once
#include "core/Component.h"
#include "core/numerics/IntegratorLimited.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type 2/2 poppet valve. The poppet (seat diameter d_1, back diameter d_2)
// opens the seat edge PS-PN when the pressures on its front faces overcome
// spring and pre-load; its motion is set by the flow through a damping
// orifice into the control chamber PC.
class Hydraulic22PoppetValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPN = nullptr, *mpPS = nullptr, *mpPC = nullptr;
    double *mpCq = nullptr, *mpRho = nullptr, *mpD1 = nullptr, *mpD2 = nullptr;
    double *mpK = nullptr, *mpF0 = nullptr, *mpF = nullptr, *mpXv = nullptr;
    double mXvmax = 0.01, mDd = 0.1e-3;
    double mAN = 0.0, mAS = 0.0, mAC = 0.0;

    double *mpPN_p = nullptr, *mpPN_q = nullptr, *mpPN_c = nullptr, *mpPN_Zc = nullptr;
    double *mpPS_p = nullptr, *mpPS_q = nullptr, *mpPS_c = nullptr, *mpPS_Zc = nullptr;
    double *mpPC_p = nullptr, *mpPC_q = nullptr, *mpPC_c = nullptr, *mpPC_Zc = nullptr;

    IntegratorLimited mX;
    TurbulentFlowFunction mQSeat, mQDamp;
};

} // namespace tlmhub
