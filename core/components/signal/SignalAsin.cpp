#include "core/components/signal/SignalAsin.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalAsin::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
    addOutputVariable("error", "1 if the input was outside the domain of the function", "", &mpError);
}

void SignalAsin::initialize()
{
    simulateOneTimestep();
}

void SignalAsin::simulateOneTimestep()
{
    const double x = *mpIn;
    if (x > 1.0) {
        *mpOut = std::asin(1.0);
        *mpError = 1.0;
    } else if (x < -1.0) {
        *mpOut = std::asin(-1.0);
        *mpError = 1.0;
    } else {
        *mpOut = std::asin(x);
        *mpError = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalAsin, "Signal")

} // namespace tlmhub
