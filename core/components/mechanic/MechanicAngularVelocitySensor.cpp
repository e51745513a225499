#include "core/components/mechanic/MechanicAngularVelocitySensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicAngularVelocitySensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::MechanicRotational, false);
    addOutputVariable("out", "AngularVelocity", "rad/s", &mpOut);
}

void MechanicAngularVelocitySensor::initialize()
{
    mpP1_val = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    // The output is valid already at t0 (logged sample 0).
    simulateOneTimestep();
}

void MechanicAngularVelocitySensor::simulateOneTimestep()
{
    *mpOut = *mpP1_val;
}

TLMHUB_REGISTER_COMPONENT(MechanicAngularVelocitySensor, "Mechanic")

} // namespace tlmhub
