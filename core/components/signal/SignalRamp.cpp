#include "core/components/signal/SignalRamp.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalRamp::configure()
{
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("t_start", "Start time", "s", 1.0, &mpTStart);
    addInputVariable("t_end", "End time", "s", 2.0, &mpTEnd);
    addOutputVariable("out", "Ramp output", "", &mpOut);
}

void SignalRamp::initialize()
{
    // The ramp formula is not applied at t0: the first sample is always y_0.
    *mpOut = *mpY0;
}

void SignalRamp::simulateOneTimestep()
{
    const double y0 = *mpY0;
    const double yA = *mpYA;
    const double ts = *mpTStart;
    const double te = *mpTEnd;
    if (mTime < ts) {
        *mpOut = y0;
    } else if (mTime < te) {
        *mpOut = ((mTime - ts) / (te - ts)) * yA + y0;
    } else {
        *mpOut = y0 + yA;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalRamp, "Signal")

} // namespace tlmhub
