#include "core/components/signal/SignalTime.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalTime::configure()
{
    addOutputVariable("out", "Simulation time", "s", &mpOut);
}

void SignalTime::initialize()
{
    *mpOut = mTime;
}

void SignalTime::simulateOneTimestep()
{
    *mpOut = mTime;
}

TLMHUB_REGISTER_COMPONENT(SignalTime, "Signal")

} // namespace tlmhub
