#include "core/components/signal/SignalQuadRoute.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalQuadRoute::configure()
{
    addInputVariable("in1", "Input 1", "", 0.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 0.0, &mpIn2);
    addInputVariable("in3", "Input 3", "", 0.0, &mpIn3);
    addInputVariable("in4", "Input 4", "", 0.0, &mpIn4);
    addInputVariable("route", "Route selector", "", 0.0, &mpRoute);
    addOutputVariable("out", "Selected input", "", &mpOut);
    addConstant("limit12", "Threshold between in1 and in2", "", 0.5, mLimit12);
    addConstant("limit23", "Threshold between in2 and in3", "", 1.5, mLimit23);
    addConstant("limit34", "Threshold between in3 and in4", "", 2.5, mLimit34);
}

void SignalQuadRoute::initialize()
{
    simulateOneTimestep();
}

void SignalQuadRoute::simulateOneTimestep()
{
    const double route = *mpRoute;
    if (route < mLimit12) {
        *mpOut = *mpIn1;
    } else if (route < mLimit23) {
        *mpOut = *mpIn2;
    } else if (route < mLimit34) {
        *mpOut = *mpIn3;
    } else {
        *mpOut = *mpIn4;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalQuadRoute, "Signal")

} // namespace tlmhub
