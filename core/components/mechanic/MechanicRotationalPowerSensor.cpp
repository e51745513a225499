#include "core/components/mechanic/MechanicRotationalPowerSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicRotationalPowerSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::MechanicRotational, false);
    // Only scales the GUI animation; not part of any equation.
    addInputVariable("PMax", "Maximum power (animation scale)", "W", 1000.0, &mpPMax);
    addOutputVariable("out", "Power", "W", &mpOut);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"PMax"}, false);
}

void MechanicRotationalPowerSensor::initialize()
{
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Torque);
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    simulateOneTimestep();
}

void MechanicRotationalPowerSensor::simulateOneTimestep()
{
    *mpOut = (*mpP1_w) * (*mpP1_T);
}

TLMHUB_REGISTER_COMPONENT(MechanicRotationalPowerSensor, "Mechanic")

} // namespace tlmhub
