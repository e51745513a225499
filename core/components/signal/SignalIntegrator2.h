#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"

namespace tlmhub {

// Trapezoidal integrator G(s) = 1/s without limits; the state starts at out#Value.
class SignalIntegrator2 : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    Integrator mIntegrator;
};

} // namespace tlmhub
