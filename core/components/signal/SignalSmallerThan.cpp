#include "core/components/signal/SignalSmallerThan.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalSmallerThan::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addInputVariable("x_limit", "Limit", "", 0.0, &mpX_limit);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalSmallerThan::initialize()
{
    simulateOneTimestep();
}

void SignalSmallerThan::simulateOneTimestep()
{
    *mpOut = boolToDouble(*mpIn < *mpX_limit);
}

TLMHUB_REGISTER_COMPONENT(SignalSmallerThan, "Signal")

} // namespace tlmhub
