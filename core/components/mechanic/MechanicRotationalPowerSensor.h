#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal sensor: mechanical power (angular velocity times torque) at a rotational node.
class MechanicRotationalPowerSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpPMax = nullptr;
    double *mpP1_w = nullptr, *mpP1_T = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
