#include "core/components/signal/SignalAnd.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalAnd::configure()
{
    addInputVariable("in1", "Input 1", "", 0.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 0.0, &mpIn2);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalAnd::initialize()
{
    simulateOneTimestep();
}

void SignalAnd::simulateOneTimestep()
{
    *mpOut = boolToDouble(doubleToBool(*mpIn1) && doubleToBool(*mpIn2));
}

TLMHUB_REGISTER_COMPONENT(SignalAnd, "Signal")

} // namespace tlmhub
