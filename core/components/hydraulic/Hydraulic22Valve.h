#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type proportional 2/2 flow control valve (P -> A) with spool dynamics.
class Hydraulic22Valve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPP = nullptr, *mpPA = nullptr;
    double *mpIn = nullptr, *mpXv = nullptr, *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr;
    double *mpF = nullptr, *mpXvmax = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;
    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mTurb;
};

} // namespace tlmhub
