#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"

namespace tlmhub {

// C-type capacitive part of a hydraulic machine: the two port volumes are TLM
// lines whose far ends are coupled through the displacement to the shaft port P3.
class HydraulicMachineC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double *mpEps = nullptr, *mpBetae = nullptr, *mpV1 = nullptr, *mpV2 = nullptr;
    double *mpDm = nullptr, *mpClm = nullptr, *mpBm = nullptr;
    double mJem = 1.0;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_t = nullptr, *mpP3_w = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;

    const double mAlfa = 0.1, mWfak = 0.1;
    double mCp1 = 0.0, mCp2 = 0.0; // wave variables at the displacement side
    double mV1min = 0.0, mV2min = 0.0;
    Delay mDC1, mDC2, mDCp1, mDCp2, mDCp1e, mDCp2e;
};

} // namespace tlmhub
