#pragma once
#include "core/Component.h"
#include "core/numerics/IntegratorLimited.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type 3/3 shuttle valve: the spool is driven by the pressure difference between PP
// and PT through two damping orifices (d_1 on the P side, d_2 on the T side). A spool
// pushed towards positive xv connects A to T, towards negative xv connects P to A.
class Hydraulic33ShuttleValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPP = nullptr, *mpPT = nullptr, *mpPA = nullptr;
    double *mpXv = nullptr;
    double *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr, *mpFpa = nullptr, *mpFat = nullptr;
    double *mpXpa = nullptr, *mpXat = nullptr;
    double mXvmax = 0.01, mD1 = 1e-3, mD2 = 1e-3;
    double mK1 = 0.0, mK2 = 0.0, mA = 0.0;

    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPT_p = nullptr, *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;

    IntegratorLimited mX;
    TurbulentFlowFunction mQpa, mQat;
};

} // namespace tlmhub
