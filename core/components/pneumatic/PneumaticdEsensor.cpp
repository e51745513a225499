#include "core/components/pneumatic/PneumaticdEsensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void PneumaticdEsensor::configure()
{
    mpPp1 = addReadPort("Pp1", NodeType::Pneumatic, false);
    addOutputVariable("out", "Energy flow", "J/s", &mpOut);
}

void PneumaticdEsensor::initialize()
{
    // An unconnected read port has its own node, so the pointer is always valid.
    mpIn = getSafeNodeDataPtr(mpPp1, NodePneumatic::EnergyFlow);
    // The output must hold the sensed start value already at t0.
    simulateOneTimestep();
}

void PneumaticdEsensor::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(PneumaticdEsensor, "Pneumatic")

} // namespace tlmhub
