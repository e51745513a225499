#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type propeller: torque load on a rotational shaft, producing thrust.
class AeroPropeller : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPmr1 = nullptr;
    double *mpUp = nullptr, *mpRho = nullptr, *mpDp = nullptr, *mpB1 = nullptr, *mpB2 = nullptr, *mpG1 = nullptr,
           *mpG2 = nullptr, *mpCt0 = nullptr, *mpCp0 = nullptr, *mpK = nullptr;
    double *mpThrust = nullptr, *mpTorque = nullptr, *mpPin = nullptr, *mpPout = nullptr, *mpJp = nullptr;
    double mThrust = 0.0, mC = 0.0;
    double *mpPmr1_w = nullptr, *mpPmr1_c = nullptr, *mpPmr1_Zc = nullptr;
};

} // namespace tlmhub
