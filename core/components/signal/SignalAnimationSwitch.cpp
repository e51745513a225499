#include "core/components/signal/SignalAnimationSwitch.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalAnimationSwitch::configure()
{
    addOutputVariable("out", "Output signal", "", &mpOut);
}

void SignalAnimationSwitch::initialize()
{
    // Nothing to set up.
}

void SignalAnimationSwitch::simulateOneTimestep()
{
    // Nothing to compute in a batch simulation.
}

TLMHUB_REGISTER_COMPONENT(SignalAnimationSwitch, "Signal")

} // namespace tlmhub
