#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDamping.h"

#include <vector>

namespace tlmhub {

// Q-type rotational inertia with viscous friction and angle limits whose two sides are
// multiports. The integrator always starts at angle 0 and speed 0.
class MechanicRotationalInertiaMultiPort : public ComponentQ {
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
    double *mpJ = nullptr, *mpB = nullptr, *mpAMin = nullptr, *mpAMax = nullptr;
};

} // namespace tlmhub
