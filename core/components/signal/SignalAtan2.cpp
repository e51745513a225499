#include "core/components/signal/SignalAtan2.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalAtan2::configure()
{
    addInputVariable("inY", "Y input", "", 0.0, &mpInY);
    addInputVariable("inX", "X input", "", 0.0, &mpInX);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalAtan2::initialize()
{
    simulateOneTimestep();
}

void SignalAtan2::simulateOneTimestep()
{
    *mpOut = std::atan2(*mpInY, *mpInX);
}

TLMHUB_REGISTER_COMPONENT(SignalAtan2, "Signal")

} // namespace tlmhub
