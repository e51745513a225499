#include "core/components/hydraulic/HydraulicPowerSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicPowerSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Hydraulic, false);
    addOutputVariable("out", "Power", "W", &mpOut);
}

void HydraulicPowerSensor::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    simulateOneTimestep();
}

void HydraulicPowerSensor::simulateOneTimestep()
{
    *mpOut = (*mpP1_p) * (*mpP1_q);
}

TLMHUB_REGISTER_COMPONENT(HydraulicPowerSensor, "Hydraulic")

} // namespace tlmhub
