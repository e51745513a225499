#pragma once
#include "core/Component.h"

namespace tlmhub {

// S-type sensor: flow of a hydraulic node (one-step lag, sensors run before C and Q).
class HydraulicFlowSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpP1_q = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
