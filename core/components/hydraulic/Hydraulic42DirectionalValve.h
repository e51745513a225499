#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type on/off 4/2 directional valve: xv = x_vmax opens P->A and B->T, xv = 0
// opens P->B and A->T, complementary openings in between.
class Hydraulic42DirectionalValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPP = nullptr, *mpPT = nullptr, *mpPA = nullptr, *mpPB = nullptr;
    double *mpIn = nullptr, *mpXv = nullptr, *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr;
    double *mpFpa = nullptr, *mpFbt = nullptr, *mpFpb = nullptr, *mpFat = nullptr, *mpXvmax = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;
    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPT_p = nullptr, *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    double *mpPB_p = nullptr, *mpPB_q = nullptr, *mpPB_c = nullptr, *mpPB_Zc = nullptr;
    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mQpa, mQpb, mQat, mQbt;
};

} // namespace tlmhub
