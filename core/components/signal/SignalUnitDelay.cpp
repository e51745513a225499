#include "core/components/signal/SignalUnitDelay.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalUnitDelay::configure()
{
    Port* pIn = addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    // Not a sort dependency: this is what lets the block break algebraic loops.
    pIn->sortHint = SortHint::IndependentDestination;
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
}

void SignalUnitDelay::initialize()
{
    *mpOut = *mpIn;
}

void SignalUnitDelay::simulateOneTimestep()
{
    *mpOut = *mpIn;
}

TLMHUB_REGISTER_COMPONENT(SignalUnitDelay, "Signal")

} // namespace tlmhub
