#include "core/components/signal/SignalSineWave.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void SignalSineWave::configure()
{
    addInputVariable("f", "Frequency", "Hz", 1.0, &mpF);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addInputVariable("y_offset", "Time offset (delay) of the wave", "s", 0.0, &mpYOffset);
    addInputVariable("t_start", "Start time", "s", 0.0, &mpTStart);
    addOutputVariable("out", "Sine wave output", "", &mpOut);
}

void SignalSineWave::initialize()
{
    simulateOneTimestep();
}

void SignalSineWave::simulateOneTimestep()
{
    const double ts = *mpTStart;
    if (mTime < ts) {
        *mpOut = 0.0;
    } else {
        // Operation order kept as in the reference for identical rounding.
        *mpOut = *mpYA * std::sin((((mTime - ts) - *mpYOffset) * 2.0) * pi * *mpF);
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSineWave, "Signal")

} // namespace tlmhub
