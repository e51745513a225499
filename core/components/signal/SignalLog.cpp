#include "core/components/signal/SignalLog.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalLog::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
    addOutputVariable("error", "1 if the input was outside the domain of the function", "", &mpError);
}

void SignalLog::initialize()
{
    simulateOneTimestep();
}

void SignalLog::simulateOneTimestep()
{
    const double x = *mpIn;
    if (x <= 0.0) {
        *mpOut = 0.0;
        *mpError = 1.0;
    } else {
        *mpOut = std::log(x);
        *mpError = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalLog, "Signal")

} // namespace tlmhub
