#include "core/components/hydraulic/HydraulicPressureSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicPressureSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Hydraulic, false);
    addOutputVariable("out", "Pressure", "Pa", &mpOut);
}

void HydraulicPressureSensor::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    simulateOneTimestep();
}

void HydraulicPressureSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_p;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureSensor, "Hydraulic")

} // namespace tlmhub
