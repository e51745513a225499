#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDamping.h"

namespace tlmhub {

// Q-type variable-displacement motor with shaft inertia; displacement scaled by
// eps in [-1, 1].
class HydraulicVariableDisplacementMotorQ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double *mpDm = nullptr, *mpBm = nullptr, *mpClm = nullptr, *mpJm = nullptr, *mpEps = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_t = nullptr, *mpP3_a = nullptr, *mpP3_w = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;
    DoubleIntegratorWithDamping mIntegrator;
};

} // namespace tlmhub
