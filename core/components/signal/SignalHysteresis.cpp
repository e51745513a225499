#include "core/components/signal/SignalHysteresis.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalHysteresis::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addInputVariable("y_h", "Total hysteresis width", "", 1.0, &mpY_h);
    addOutputVariable("out", "Output signal", "", &mpOut);
}

void SignalHysteresis::initialize()
{
    mDelay.initialize(1, *mpIn);
    *mpOut = *mpIn;
}

void SignalHysteresis::simulateOneTimestep()
{
    const double y = mHyst.getValue(*mpIn, *mpY_h, mDelay.getOldest());
    *mpOut = y;
    mDelay.update(y);
}

TLMHUB_REGISTER_COMPONENT(SignalHysteresis, "Signal")

} // namespace tlmhub
