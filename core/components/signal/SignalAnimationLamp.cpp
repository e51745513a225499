#include "core/components/signal/SignalAnimationLamp.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalAnimationLamp::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"in"}, false);
}

void SignalAnimationLamp::initialize()
{
    // Nothing to set up.
}

void SignalAnimationLamp::simulateOneTimestep()
{
    // Nothing to compute in a batch simulation.
}

TLMHUB_REGISTER_COMPONENT(SignalAnimationLamp, "Signal")

} // namespace tlmhub
