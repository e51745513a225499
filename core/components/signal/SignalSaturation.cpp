#include "core/components/signal/SignalSaturation.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalSaturation::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addInputVariable("y_upper", "Upper limit", "", 1.0, &mpY_upper);
    addInputVariable("y_lower", "Lower limit", "", -1.0, &mpY_lower);
    addOutputVariable("out", "Output signal", "", &mpOut);
}

void SignalSaturation::initialize()
{
    simulateOneTimestep();
}

void SignalSaturation::simulateOneTimestep()
{
    const double u = *mpIn;
    if (u > *mpY_upper) {
        *mpOut = *mpY_upper;
    } else if (u < *mpY_lower) {
        *mpOut = *mpY_lower;
    } else {
        *mpOut = u;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSaturation, "Signal")

} // namespace tlmhub
