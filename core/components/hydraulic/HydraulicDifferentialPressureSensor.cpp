#include "core/components/hydraulic/HydraulicDifferentialPressureSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicDifferentialPressureSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Hydraulic, false);
    mpP2 = addReadPort("P2", NodeType::Hydraulic, false);
    addOutputVariable("out", "Pressure difference", "Pa", &mpOut);
}

void HydraulicDifferentialPressureSensor::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    simulateOneTimestep();
}

void HydraulicDifferentialPressureSensor::simulateOneTimestep()
{
    *mpOut = *mpP1_p - *mpP2_p;
}

TLMHUB_REGISTER_COMPONENT(HydraulicDifferentialPressureSensor, "Hydraulic")

} // namespace tlmhub
