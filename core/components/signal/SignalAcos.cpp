#include "core/components/signal/SignalAcos.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalAcos::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
    addOutputVariable("error", "1 if the input was outside the domain of the function", "", &mpError);
}

void SignalAcos::initialize()
{
    simulateOneTimestep();
}

void SignalAcos::simulateOneTimestep()
{
    const double x = *mpIn;
    if (x > 1.0) {
        *mpOut = std::acos(1.0);
        *mpError = 1.0;
    } else if (x < -1.0) {
        *mpOut = std::acos(-1.0);
        *mpError = 1.0;
    } else {
        *mpOut = std::acos(x);
        *mpError = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalAcos, "Signal")

} // namespace tlmhub
