#pragma once
#include "core/Component.h"

namespace tlmhub {

// S-type sensor: pressure difference P1 - P2 (one-step lag, sensors run before C and Q).
class HydraulicDifferentialPressureSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double* mpP1_p = nullptr;
    double* mpP2_p = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
