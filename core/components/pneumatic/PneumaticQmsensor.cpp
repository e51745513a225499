#include "core/components/pneumatic/PneumaticQmsensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void PneumaticQmsensor::configure()
{
    mpPp1 = addReadPort("Pp1", NodeType::Pneumatic, false);
    addOutputVariable("out", "Mass flow", "kg/s", &mpOut);
}

void PneumaticQmsensor::initialize()
{
    // An unconnected read port has its own node, so the pointer is always valid.
    mpIn = getSafeNodeDataPtr(mpPp1, NodePneumatic::MassFlow);
    // The output must hold the sensed start value already at t0.
    simulateOneTimestep();
}

void PneumaticQmsensor::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(PneumaticQmsensor, "Pneumatic")

} // namespace tlmhub
