#include "core/components/signal/SignalGreaterThan.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalGreaterThan::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addInputVariable("x_limit", "Limit", "", 0.0, &mpX_limit);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalGreaterThan::initialize()
{
    simulateOneTimestep();
}

void SignalGreaterThan::simulateOneTimestep()
{
    *mpOut = boolToDouble(*mpIn > *mpX_limit);
}

TLMHUB_REGISTER_COMPONENT(SignalGreaterThan, "Signal")

} // namespace tlmhub
