#include "core/components/hydraulic/HydraulicQSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicQSource::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("in_p", "Pressure", "Pa", 0.0, &mpInP);
    addInputVariable("in_q", "Flow", "m^3/s", 0.0, &mpInQ);
}

void HydraulicQSource::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    simulateOneTimestep();
}

void HydraulicQSource::simulateOneTimestep()
{
    *mpP1_p = *mpInP;
    *mpP1_q = *mpInQ;
}

TLMHUB_REGISTER_COMPONENT(HydraulicQSource, "Hydraulic")

} // namespace tlmhub
