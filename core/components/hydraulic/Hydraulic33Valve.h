#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type 3/3 directional valve: a second-order spool following `in` opens P-A for
// xv > 0 and A-T for xv < 0; the centre is closed apart from the overlap leakage.
class Hydraulic33Valve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPP = nullptr, *mpPT = nullptr, *mpPA = nullptr;
    double *mpIn = nullptr, *mpXv = nullptr;
    double *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr, *mpFpa = nullptr, *mpFat = nullptr;
    double *mpXvmax = nullptr, *mpXpa = nullptr, *mpXat = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;

    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPT_p = nullptr, *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;

    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mQpa, mQat;
};

} // namespace tlmhub
