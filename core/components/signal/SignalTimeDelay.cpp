#include "core/components/signal/SignalTimeDelay.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalTimeDelay::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", &mpOut);
    addConstant("deltat", "Time delay", "s", 1.0, mDeltat);
}

void SignalTimeDelay::initialize()
{
    mDelay.initialize(mDeltat, mTimestep, *mpIn);
    *mpOut = *mpIn;
}

void SignalTimeDelay::simulateOneTimestep()
{
    *mpOut = mDelay.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalTimeDelay, "Signal")

} // namespace tlmhub
