#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type pilot operated 2/2 valve, normally closed: the pilot wave variable at PC
// opens P -> A between Fs_min and Fs_max.
class HydraulicPressureControlled22Valve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPP = nullptr;
    Port* mpPA = nullptr;
    Port* mpPC = nullptr;
    double *mpFsmin = nullptr, *mpFsmax = nullptr, *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr;
    double* mpfpa = nullptr;
    double* mpfbt = nullptr;
    double *mpXvmax = nullptr, *mpXv = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;
    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    double *mpPC_p = nullptr, *mpPC_q = nullptr, *mpPC_c = nullptr, *mpPC_Zc = nullptr;
    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mQpa;
};

} // namespace tlmhub
