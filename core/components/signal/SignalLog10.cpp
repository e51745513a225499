#include "core/components/signal/SignalLog10.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalLog10::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
    addOutputVariable("error", "1 if the input was outside the domain of the function", "", &mpError);
}

void SignalLog10::initialize()
{
    simulateOneTimestep();
}

void SignalLog10::simulateOneTimestep()
{
    const double x = *mpIn;
    if (x <= 0.0) {
        *mpOut = 0.0;
        *mpError = 1.0;
    } else {
        *mpOut = std::log10(x);
        *mpError = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalLog10, "Signal")

} // namespace tlmhub
