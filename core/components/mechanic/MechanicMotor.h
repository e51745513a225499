#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/Integrator.h"

namespace tlmhub {

// C-type speed-controlled motor: a PID on the angular velocity error gives a torque
// imposed as a zero-impedance wave.
class MechanicMotor : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpOmegaRef = nullptr, *mpKp = nullptr, *mpKi = nullptr, *mpKd = nullptr;
    double *mpP1_w = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    Integrator mIntegrator;
    FirstOrderTransferFunction mDerivator;
};

} // namespace tlmhub
