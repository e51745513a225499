#pragma once
#include "core/Component.h"

namespace tlmhub {

// S-type sensor: all four TLM variables of a hydraulic node (one-step lag, sensors run before C and Q).
class HydraulicNodeSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpOutP = nullptr, *mpOutQ = nullptr, *mpOutC = nullptr, *mpOutZc = nullptr;
};

} // namespace tlmhub
