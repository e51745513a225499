#include "core/components/signal/SignalSoftStep.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void SignalSoftStep::configure()
{
    addInputVariable("t_start", "Start time", "s", 1.0, &mpTStart);
    addInputVariable("t_end", "End time", "s", 2.0, &mpTEnd);
    addInputVariable("y_0", "Base value", "", 0.0, &mpY0);
    addInputVariable("y_A", "Amplitude", "", 1.0, &mpYA);
    addOutputVariable("out", "Soft step output", "", &mpOut);
}

void SignalSoftStep::initialize()
{
    *mpOut = *mpY0;
}

void SignalSoftStep::simulateOneTimestep()
{
    const double ts = *mpTStart;
    const double te = *mpTEnd;
    const double y0 = *mpY0;
    const double yA = *mpYA;
    const double w = pi / (te - ts);
    if (mTime < ts) {
        *mpOut = y0;
    } else if (mTime < te) {
        *mpOut = y0 + 0.5 * yA * std::sin((mTime - ts) * w - pi / 2.0) + 0.5 * yA;
    } else {
        *mpOut = y0 + yA;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSoftStep, "Signal")

} // namespace tlmhub
