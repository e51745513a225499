#include "core/components/pneumatic/PneumaticTsensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void PneumaticTsensor::configure()
{
    mpPp1 = addReadPort("Pp1", NodeType::Pneumatic, false);
    addOutputVariable("out", "Temperature", "K", &mpOut);
}

void PneumaticTsensor::initialize()
{
    // An unconnected read port has its own node, so the pointer is always valid.
    mpIn = getSafeNodeDataPtr(mpPp1, NodePneumatic::Temperature);
    // The output must hold the sensed start value already at t0.
    simulateOneTimestep();
}

void PneumaticTsensor::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(PneumaticTsensor, "Pneumatic")

} // namespace tlmhub
