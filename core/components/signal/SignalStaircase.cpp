#include "core/components/signal/SignalStaircase.h"

#include "core/ComponentFactory.h"

#include <cmath>
#include <algorithm>

namespace tlmhub {

void SignalStaircase::configure()
{
    addInputVariable("T_start", "Start time", "s", 0.0, &mpTStart);
    addInputVariable("H_step", "Step height", "", 1.0, &mpHStep);
    addInputVariable("W_step", "Step width", "s", 1.0, &mpWStep);
    addOutputVariable("out", "Staircase output", "", 0.0, &mpOut);
}

void SignalStaircase::initialize()
{
    // Nothing computed: the t0 sample is the start value out#Value.
}

void SignalStaircase::simulateOneTimestep()
{
    const double wStep = *mpWStep;
    // Half a (time or stair) step of bias so exact multiples are not missed by rounding.
    const double arg = (mTime - *mpTStart) + 0.5 * std::min(mTimestep, wStep);
    *mpOut = *mpHStep * std::floor(std::max(0.0, arg) / wStep);
}

TLMHUB_REGISTER_COMPONENT(SignalStaircase, "Signal")

} // namespace tlmhub
