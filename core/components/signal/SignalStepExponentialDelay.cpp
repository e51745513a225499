#include "core/components/signal/SignalStepExponentialDelay.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalStepExponentialDelay::configure()
{
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("tao", "Time constant", "", 1.0, &mpTao);
    addInputVariable("t_step", "Step time", "s", 1.0, &mpTStep);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalStepExponentialDelay::initialize()
{
    *mpOut = *mpY0;
}

void SignalStepExponentialDelay::simulateOneTimestep()
{
    const double tStep = *mpTStep;
    if (mTime < tStep) {
        *mpOut = *mpY0;
    } else {
        *mpOut = *mpY0 + *mpYA * std::exp(-(mTime - tStep) / *mpTao);
    }
}

TLMHUB_REGISTER_COMPONENT(SignalStepExponentialDelay, "Signal")

} // namespace tlmhub
