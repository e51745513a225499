#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDamping.h"

#include <vector>

namespace tlmhub {

// Q-type translational mass with viscous friction and end stops whose two sides are
// multiports; forces and impedances of all connections on a side are summed.
class MechanicMultiPortTranslationalMass : public ComponentQ {
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
    DoubleIntegratorWithDamping mIntegrator;
    double *mpM = nullptr, *mpB = nullptr, *mpXMin = nullptr, *mpXMax = nullptr;
};

} // namespace tlmhub
