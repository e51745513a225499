#include "core/components/signal/SignalNumericalInput.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalNumericalInput::configure()
{
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
}

void SignalNumericalInput::initialize()
{
    // Nothing to set up.
}

void SignalNumericalInput::simulateOneTimestep()
{
    // Nothing to compute in a batch simulation.
}

TLMHUB_REGISTER_COMPONENT(SignalNumericalInput, "Signal")

} // namespace tlmhub
