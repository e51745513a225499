#include "core/components/mechanic/MechanicTorqueSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTorqueSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::MechanicRotational, false);
    addOutputVariable("out", "Torque", "Nm", &mpOut);
}

void MechanicTorqueSensor::initialize()
{
    mpP1_val = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Torque);
    // The output is valid already at t0 (logged sample 0).
    simulateOneTimestep();
}

void MechanicTorqueSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_val;
}

TLMHUB_REGISTER_COMPONENT(MechanicTorqueSensor, "Mechanic")

} // namespace tlmhub
