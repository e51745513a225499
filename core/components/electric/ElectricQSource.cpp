#include "core/components/electric/ElectricQSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricQSource::configure()
{
    addInputVariable("in_u", "Voltage input", "V", 0.0, &mpInU);
    addInputVariable("in_i", "Current input", "A", 0.0, &mpInI);
    mpP1 = addPowerPort("P1", NodeType::Electric);
}

void ElectricQSource::initialize()
{
    mpP1_u = getSafeNodeDataPtr(mpP1, NodeElectric::Voltage);
    mpP1_i = getSafeNodeDataPtr(mpP1, NodeElectric::Current);
    simulateOneTimestep();
}

void ElectricQSource::simulateOneTimestep()
{
    *mpP1_u = *mpInU;
    *mpP1_i = *mpInI;
}

TLMHUB_REGISTER_COMPONENT(ElectricQSource, "Electric")

} // namespace tlmhub
