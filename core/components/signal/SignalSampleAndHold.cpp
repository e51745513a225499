#include "core/components/signal/SignalSampleAndHold.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalSampleAndHold::configure()
{
    addInputVariable("f_s", "Sampling frequency", "Hz", 100.0, &mpF_s);
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", &mpOut);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"f_s"}, false);
}

void SignalSampleAndHold::initialize()
{
    *mpOut = *mpIn;
    mTnext = mTime;
    mTs = 1.0 / (*mpF_s);
}

void SignalSampleAndHold::simulateOneTimestep()
{
    if (mTime >= mTnext) {
        *mpOut = *mpIn;
        mTnext = mTnext + mTs;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSampleAndHold, "Signal")

} // namespace tlmhub
