#include "core/components/signal/SignalRound.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalRound::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalRound::initialize()
{
    simulateOneTimestep();
}

void SignalRound::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::round(x);
}

TLMHUB_REGISTER_COMPONENT(SignalRound, "Signal")

} // namespace tlmhub
