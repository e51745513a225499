#include "core/components/pneumatic/PneumaticPsensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void PneumaticPsensor::configure()
{
    mpPp1 = addReadPort("Pp1", NodeType::Pneumatic, false);
    addOutputVariable("out", "Pressure", "Pa", &mpOut);
}

void PneumaticPsensor::initialize()
{
    // An unconnected read port has its own node, so the pointer is always valid.
    mpIn = getSafeNodeDataPtr(mpPp1, NodePneumatic::Pressure);
    // The output must hold the sensed start value already at t0.
    simulateOneTimestep();
}

void PneumaticPsensor::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(PneumaticPsensor, "Pneumatic")

} // namespace tlmhub
