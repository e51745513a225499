#include "core/components/signal/SignalCounter.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalCounter::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Number of counted edges", "", &mpOut);
    addConstant("r", "Count rising edges", true, mRising);
    addConstant("f", "Count falling edges", true, mFalling);
}

void SignalCounter::initialize()
{
    // prev starts false, so an input already high at the first step counts as a rising edge.
    mPrev = false;
    *mpOut = 0.0;
}

void SignalCounter::simulateOneTimestep()
{
    const bool b = doubleToBool(*mpIn);
    if (mRising && b && !mPrev) {
        *mpOut = *mpOut + 1.0;
    } else if (mFalling && !b && mPrev) {
        *mpOut = *mpOut + 1.0;
    }
    mPrev = b;
}

TLMHUB_REGISTER_COMPONENT(SignalCounter, "Signal")

} // namespace tlmhub
