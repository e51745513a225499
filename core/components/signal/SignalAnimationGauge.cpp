#include "core/components/signal/SignalAnimationGauge.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalAnimationGauge::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addConstant("max", "Full-scale value (display only)", "", 1.0, mMax);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"in"}, false);
}

void SignalAnimationGauge::initialize()
{
    // Nothing to set up.
}

void SignalAnimationGauge::simulateOneTimestep()
{
    // Nothing to compute in a batch simulation.
}

TLMHUB_REGISTER_COMPONENT(SignalAnimationGauge, "Signal")

} // namespace tlmhub
