#include "core/components/electric/ElectricUsensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricUsensor::configure()
{
    mpPel1 = addReadPort("Pel1", NodeType::Electric, false);
    addOutputVariable("Puout", "Voltage", "V", &mpOut);
}

void ElectricUsensor::initialize()
{
    // An unconnected read port has its own node, so the pointer is always valid.
    mpIn = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    // The output must hold the sensed start value already at t0.
    simulateOneTimestep();
}

void ElectricUsensor::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(ElectricUsensor, "Electric")

} // namespace tlmhub
