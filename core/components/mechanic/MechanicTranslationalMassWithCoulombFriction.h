#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDampingAndCoulombFriction.h"

namespace tlmhub {

// Q-type mass with viscous friction, static/kinetic Coulomb friction and end stops on
// the P2 position.
class MechanicTranslationalMassWithCoulombFriction : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mMass = 100.0;
    double mLength = 0.0;
    double *mpB = nullptr, *mpFs = nullptr, *mpFk = nullptr, *mpXMin = nullptr, *mpXMax = nullptr;
    double *mpP1_f = nullptr, *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr, *mpP1_me = nullptr;
    double *mpP2_f = nullptr, *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr, *mpP2_me = nullptr;
    DoubleIntegratorWithDampingAndCoulombFriction mIntegrator;
};

} // namespace tlmhub
