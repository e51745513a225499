#include "core/components/electric/ElectricIsensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricIsensor::configure()
{
    mpPel1 = addReadPort("Pel1", NodeType::Electric, false);
    addOutputVariable("Piout", "Current", "A", &mpOut);
}

void ElectricIsensor::initialize()
{
    // An unconnected read port has its own node, so the pointer is always valid.
    mpIn = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    // The output must hold the sensed start value already at t0.
    simulateOneTimestep();
}

void ElectricIsensor::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(ElectricIsensor, "Electric")

} // namespace tlmhub
