#include "core/components/mechanic/MechanicAngleSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicAngleSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::MechanicRotational, false);
    addOutputVariable("out", "Angle", "rad", &mpOut);
}

void MechanicAngleSensor::initialize()
{
    mpP1_val = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Angle);
    // The output is valid already at t0 (logged sample 0).
    simulateOneTimestep();
}

void MechanicAngleSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_val;
}

TLMHUB_REGISTER_COMPONENT(MechanicAngleSensor, "Mechanic")

} // namespace tlmhub
