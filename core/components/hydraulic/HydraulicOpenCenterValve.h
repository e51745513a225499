#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type symmetric 4/3 proportional valve (as Hydraulic43Valve) with an extra
// open-centre gallery C1 -> C2 that is open at centre and closes towards +-x_vmax.
class HydraulicOpenCenterValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPP = nullptr, *mpPT = nullptr, *mpPA = nullptr, *mpPB = nullptr, *mpPC1 = nullptr, *mpPC2 = nullptr;
    double *mpIn = nullptr, *mpXv = nullptr;
    double *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr;
    double *mpFpa = nullptr, *mpFpb = nullptr, *mpFat = nullptr, *mpFbt = nullptr, *mpFcc = nullptr;
    double *mpXpa = nullptr, *mpXpb = nullptr, *mpXat = nullptr, *mpXbt = nullptr, *mpXcc = nullptr;
    double *mpXvmax = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;

    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPT_p = nullptr, *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    double *mpPB_p = nullptr, *mpPB_q = nullptr, *mpPB_c = nullptr, *mpPB_Zc = nullptr;
    double *mpPC1_p = nullptr, *mpPC1_q = nullptr, *mpPC1_c = nullptr, *mpPC1_Zc = nullptr;
    double *mpPC2_p = nullptr, *mpPC2_q = nullptr, *mpPC2_c = nullptr, *mpPC2_Zc = nullptr;

    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mQpa, mQpb, mQat, mQbt, mQcc;
};

} // namespace tlmhub
