#include "core/components/hydraulic/HydraulicFlowSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicFlowSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Hydraulic, false);
    addOutputVariable("out", "Flow", "m^3/s", &mpOut);
}

void HydraulicFlowSensor::initialize()
{
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    simulateOneTimestep();
}

void HydraulicFlowSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_q;
}

TLMHUB_REGISTER_COMPONENT(HydraulicFlowSensor, "Hydraulic")

} // namespace tlmhub
