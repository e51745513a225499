#include "core/components/signal/SignalPulseWave.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalPulseWave::configure()
{
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("t_start", "Start time", "s", 0.0, &mpTStart);
    addInputVariable("dT", "Period", "s", 1.0, &mpDT);
    addInputVariable("D", "Duty cycle (0..1)", "", 0.5, &mpD);
    addOutputVariable("out", "Pulse wave output", "", &mpOut);
}

void SignalPulseWave::initialize()
{
    *mpOut = *mpY0;
}

void SignalPulseWave::simulateOneTimestep()
{
    const double dT = *mpDT;
    // Half a step of bias so that period boundaries do not depend on time rounding.
    const double tau = (mTime - *mpTStart) + 0.5 * mTimestep;
    const double phase = tau - std::floor(tau / dT) * dT;
    const bool high = phase < *mpD * dT;
    if (tau > 0.0 && high) {
        *mpOut = *mpY0 + *mpYA;
    } else {
        *mpOut = *mpY0;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalPulseWave, "Signal")

} // namespace tlmhub
