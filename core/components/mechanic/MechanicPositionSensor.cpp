#include "core/components/mechanic/MechanicPositionSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicPositionSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Mechanic, false);
    addOutputVariable("out", "Position", "m", &mpOut);
}

void MechanicPositionSensor::initialize()
{
    mpP1_val = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    // The output is valid already at t0 (logged sample 0).
    simulateOneTimestep();
}

void MechanicPositionSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_val;
}

TLMHUB_REGISTER_COMPONENT(MechanicPositionSensor, "Mechanic")

} // namespace tlmhub
