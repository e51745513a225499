#pragma once
#include "core/Component.h"

namespace tlmhub {

// S-type sensor: hydraulic power p*q at a node (one-step lag, sensors run before C and Q).
class HydraulicPowerSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpP1_p = nullptr;
    double* mpP1_q = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
