#include "core/components/mechanic/MechanicForceSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicForceSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Mechanic, false);
    addOutputVariable("out", "Force", "N", &mpOut);
}

void MechanicForceSensor::initialize()
{
    mpP1_val = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    // The output is valid already at t0 (logged sample 0).
    simulateOneTimestep();
}

void MechanicForceSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_val;
}

TLMHUB_REGISTER_COMPONENT(MechanicForceSensor, "Mechanic")

} // namespace tlmhub
