#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"

namespace tlmhub {

// Q-type ideal angular velocity source; the angle is the integral of the input.
class MechanicAngularVelocityTransformer : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpOut = nullptr;
    double* mpOmega = nullptr;
    double *mpOut_T = nullptr, *mpOut_a = nullptr, *mpOut_w = nullptr, *mpOut_c = nullptr,
           *mpOut_Zc = nullptr;
    Integrator mIntegrator;
};

} // namespace tlmhub
