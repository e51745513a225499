#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type proportional symmetric 4/3 spool valve (flow model as Hydraulic43Valve)
// with a load-sensing port PL reporting the pressure of the pressurised load port.
class Hydraulic43LoadSensingValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPP = nullptr, *mpPT = nullptr, *mpPA = nullptr, *mpPB = nullptr, *mpPL = nullptr;
    double *mpIn = nullptr, *mpXv = nullptr;
    double *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr;
    double *mpFpa = nullptr, *mpFpb = nullptr, *mpFat = nullptr, *mpFbt = nullptr;
    double *mpXpa = nullptr, *mpXpb = nullptr, *mpXat = nullptr, *mpXbt = nullptr;
    double *mpXvmax = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;

    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPT_p = nullptr, *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    double *mpPB_p = nullptr, *mpPB_q = nullptr, *mpPB_c = nullptr, *mpPB_Zc = nullptr;
    double *mpPL_p = nullptr, *mpPL_q = nullptr, *mpPL_c = nullptr, *mpPL_Zc = nullptr;

    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mQpa, mQpb, mQat, mQbt;
};

} // namespace tlmhub
