#include "core/components/hydraulic/HydraulicCSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicCSource::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("in_c", "Wave variable", "Pa", 0.0, &mpInC);
    addInputVariable("in_z", "Characteristic impedance", "Pa s/m^3", 0.0, &mpInZ);
    disableStartValue(mpP1, NodeHydraulic::WaveVariable);
    disableStartValue(mpP1, NodeHydraulic::CharImpedance);
}

void HydraulicCSource::initialize()
{
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    simulateOneTimestep();
}

void HydraulicCSource::simulateOneTimestep()
{
    *mpP1_c = *mpInC;
    *mpP1_Zc = *mpInZ;
}

TLMHUB_REGISTER_COMPONENT(HydraulicCSource, "Hydraulic")

} // namespace tlmhub
