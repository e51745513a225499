#pragma once
#include "core/Component.h"

namespace tlmhub {

// S-type sensor: pressure of a hydraulic node (one-step lag, sensors run before C and Q).
class HydraulicPressureSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpP1_p = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
