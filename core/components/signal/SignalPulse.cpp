#include "core/components/signal/SignalPulse.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalPulse::configure()
{
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("t_start", "Start time", "s", 1.0, &mpTStart);
    addInputVariable("t_end", "End time", "s", 2.0, &mpTEnd);
    addOutputVariable("out", "Pulse output", "", &mpOut);
}

void SignalPulse::initialize()
{
    *mpOut = *mpY0;
}

void SignalPulse::simulateOneTimestep()
{
    const double tm = mTime + 0.5 * mTimestep;
    if (tm >= *mpTStart && tm < *mpTEnd) {
        *mpOut = *mpY0 + *mpYA;
    } else {
        *mpOut = *mpY0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalPulse, "Signal")

} // namespace tlmhub
