#include "core/components/signal/SignalNot.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalNot::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalNot::initialize()
{
    simulateOneTimestep();
}

void SignalNot::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = boolToDouble(!doubleToBool(x));
}

TLMHUB_REGISTER_COMPONENT(SignalNot, "Signal")

} // namespace tlmhub
