#include "core/components/signal/SignalStep.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalStep::configure()
{
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("t_step", "Step time", "s", 1.0, &mpTStep);
    addOutputVariable("out", "Step output", "", &mpOut);
}

void SignalStep::initialize()
{
    // The step is evaluated at t0 too, so t0 >= t_step already gives the stepped value.
    simulateOneTimestep();
}

void SignalStep::simulateOneTimestep()
{
    if (mTime < *mpTStep) {
        *mpOut = *mpY0;
    } else {
        *mpOut = *mpY0 + *mpYA;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalStep, "Signal")

} // namespace tlmhub
