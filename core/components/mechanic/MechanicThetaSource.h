#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"

namespace tlmhub {

// Q-type ideal angle / angular velocity source. Without a connected angle input the
// angle is the integral of the angular velocity.
class MechanicThetaSource : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPmr1 = nullptr;
    Port* mpThetaPort = nullptr;
    double *mpTheta = nullptr, *mpOmega = nullptr;
    double *mpPmr1_T = nullptr, *mpPmr1_a = nullptr, *mpPmr1_w = nullptr, *mpPmr1_c = nullptr,
           *mpPmr1_Zc = nullptr;
    bool mThetaConnected = false;
    Integrator mIntegrator;
};

} // namespace tlmhub
