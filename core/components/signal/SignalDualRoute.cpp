#include "core/components/signal/SignalDualRoute.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalDualRoute::configure()
{
    addInputVariable("in1", "Input 1", "", 0.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 0.0, &mpIn2);
    addInputVariable("route", "Route selector", "", 0.0, &mpRoute);
    addOutputVariable("out", "Selected input", "", &mpOut);
    addConstant("limit", "Threshold between in1 and in2", "", 0.5, mLimit);
}

void SignalDualRoute::initialize()
{
    simulateOneTimestep();
}

void SignalDualRoute::simulateOneTimestep()
{
    if (*mpRoute < mLimit) {
        *mpOut = *mpIn1;
    } else {
        *mpOut = *mpIn2;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalDualRoute, "Signal")

} // namespace tlmhub
