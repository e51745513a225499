#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDampingAndCoulombFriction.h"

#include <vector>

namespace tlmhub {

// Q-type multiport version of MechanicTranslationalMassWithCoulombFriction.
class MechanicTranslationalMassWithCoulombFrictionAndMultiPorts : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    struct SubPort {
        double* f;
        double* x;
        double* v;
        double* c;
        double* Zc;
        double* me;
        double xStart;
    };
    void bindSide(Port* port, std::vector<SubPort>& side);

    Port *mpP1 = nullptr, *mpP2 = nullptr;
    std::vector<SubPort> mP1, mP2;
    DoubleIntegratorWithDampingAndCoulombFriction mIntegrator;
    double mMass = 100.0;
    double *mpB = nullptr, *mpFs = nullptr, *mpFk = nullptr, *mpXMin = nullptr, *mpXMax = nullptr;
};

} // namespace tlmhub
