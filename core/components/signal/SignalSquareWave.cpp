#include "core/components/signal/SignalSquareWave.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void SignalSquareWave::configure()
{
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("f", "Frequency", "Hz", 1.0, &mpF);
    addInputVariable("t_start", "Start time", "s", 0.0, &mpTStart);
    addOutputVariable("out", "Square wave output", "", &mpOut);
}

void SignalSquareWave::initialize()
{
    // Not evaluated at t0: the first sample is y_0.
    *mpOut = *mpY0;
}

void SignalSquareWave::simulateOneTimestep()
{
    const double ts = *mpTStart;
    if (mTime < ts) {
        *mpOut = *mpY0;
    } else {
        // Edges depend on the rounding of sin near multiples of pi: keep this order.
        const double s = std::sin((((mTime - ts) * 2.0) * pi) * *mpF);
        if (s >= 0.0) {
            *mpOut = *mpY0 + *mpYA;
        } else {
            *mpOut = *mpY0 - *mpYA;
        }
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSquareWave, "Signal")

} // namespace tlmhub
