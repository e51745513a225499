#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"

namespace tlmhub {

// Q-type ideal velocity (and position) source for a translational port.
class MechanicVelocityTransformer : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPm1 = nullptr;
    Port* mpXPort = nullptr;
    double mMe = 10.0;
    double *mpV = nullptr, *mpX = nullptr;
    double *mpPm1_f = nullptr, *mpPm1_x = nullptr, *mpPm1_v = nullptr, *mpPm1_c = nullptr,
           *mpPm1_Zx = nullptr, *mpPm1_me = nullptr;
    bool mXConnected = false;
    Integrator mIntegrator;
};

} // namespace tlmhub
