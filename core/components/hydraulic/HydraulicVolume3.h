#pragma once
#include "core/Component.h"

namespace tlmhub {

// Obsolete C-type three-port hydraulic volume (old multicore benchmark models).
class HydraulicVolume3 : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double mVolume = 1.0e-3, mBetae = 1.0e9, mAlpha = 0.1;
    double mZc = 0.0;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_p = nullptr, *mpP3_q = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;
};

} // namespace tlmhub
