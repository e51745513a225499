#include "core/components/signal/SignalSqrt.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalSqrt::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
    addOutputVariable("error", "1 if the input was outside the domain of the function", "", &mpError);
}

void SignalSqrt::initialize()
{
    simulateOneTimestep();
}

void SignalSqrt::simulateOneTimestep()
{
    const double x = *mpIn;
    if (x < 0.0) {
        *mpOut = 0.0;
        *mpError = 1.0;
    } else {
        *mpOut = std::sqrt(x);
        *mpError = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSqrt, "Signal")

} // namespace tlmhub
