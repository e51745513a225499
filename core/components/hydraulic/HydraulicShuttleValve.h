#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type ideal shuttle (OR) valve: the inlet with the higher pressure is connected
// to P3 without restriction, the other one is blocked.
class HydraulicShuttleValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double* mpOut = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_p = nullptr, *mpP3_q = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;
};

} // namespace tlmhub
