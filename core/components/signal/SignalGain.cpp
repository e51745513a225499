#include "core/components/signal/SignalGain.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalGain::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addInputVariable("k", "Gain", "", 1.0, &mpK);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalGain::initialize()
{
    simulateOneTimestep();
}

void SignalGain::simulateOneTimestep()
{
    *mpOut = *mpK * *mpIn;
}

TLMHUB_REGISTER_COMPONENT(SignalGain, "Signal")

} // namespace tlmhub
