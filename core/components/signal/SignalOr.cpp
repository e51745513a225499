#include "core/components/signal/SignalOr.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalOr::configure()
{
    addInputVariable("in1", "Input 1", "", 0.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 0.0, &mpIn2);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalOr::initialize()
{
    simulateOneTimestep();
}

void SignalOr::simulateOneTimestep()
{
    *mpOut = boolToDouble(doubleToBool(*mpIn1) || doubleToBool(*mpIn2));
}

TLMHUB_REGISTER_COMPONENT(SignalOr, "Signal")

} // namespace tlmhub
