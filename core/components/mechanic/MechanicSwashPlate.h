#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"

#include <vector>

namespace tlmhub {

// Swash plate driving n pistons (one per sub-port of the mechanic multiport P1), spread
// evenly around the shaft. The shaft speed `movement` is an input, integrated to the shaft
// angle; the pistons' positions and speeds follow, and their forces give the shaft torque.
class MechanicSwashPlate : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    struct Piston {
        double* f;
        double* x;
        double* v;
        double* c;
        double* Zc;
    };

    Port* mpP1 = nullptr;
    double* mpR = nullptr;
    double* mpOffset = nullptr;
    double* mpAngle = nullptr;
    double* mpMovement = nullptr;
    double* mpTorque = nullptr;
    std::vector<Piston> mPistons;
    Integrator mShaftAngle;
};

} // namespace tlmhub
