#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDampingAndCoulombFriction.h"

namespace tlmhub {

// Q-type rotational inertia with viscous friction, static/kinetic Coulomb friction and
// angle limits on P2.
class MechanicRotationalInertiaWithCoulombFriction : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mTs = 50.0, mTk = 45.0;
    double *mpJ = nullptr, *mpB = nullptr, *mpAMin = nullptr, *mpAMax = nullptr;
    double *mpP1_T = nullptr, *mpP1_a = nullptr, *mpP1_w = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr;
    double *mpP2_T = nullptr, *mpP2_a = nullptr, *mpP2_w = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr;
    DoubleIntegratorWithDampingAndCoulombFriction mIntegrator;
};

} // namespace tlmhub
