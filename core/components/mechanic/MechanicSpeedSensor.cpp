#include "core/components/mechanic/MechanicSpeedSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicSpeedSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Mechanic, false);
    addOutputVariable("out", "Velocity", "m/s", &mpOut);
}

void MechanicSpeedSensor::initialize()
{
    mpP1_val = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    // The output is valid already at t0 (logged sample 0).
    simulateOneTimestep();
}

void MechanicSpeedSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_val;
}

TLMHUB_REGISTER_COMPONENT(MechanicSpeedSensor, "Mechanic")

} // namespace tlmhub
