#include "core/components/electric/ElectricCSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricCSource::configure()
{
    addInputVariable("in_c", "Wave variable input", "V", 0.0, &mpInC);
    addInputVariable("in_z", "Characteristic impedance input", "V/A", 0.0, &mpInZ);
    mpP1 = addPowerPort("P1", NodeType::Electric);
}

void ElectricCSource::initialize()
{
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeElectric::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeElectric::CharImpedance);
    simulateOneTimestep();
}

void ElectricCSource::simulateOneTimestep()
{
    *mpP1_c = *mpInC;
    *mpP1_Zc = *mpInZ;
}

TLMHUB_REGISTER_COMPONENT(ElectricCSource, "Electric")

} // namespace tlmhub
