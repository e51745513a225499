#include "core/components/signal/SignalTimestep.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalTimestep::configure()
{
    addOutputVariable("ts", "Time step", "s", &mpTs);
}

void SignalTimestep::initialize()
{
    *mpTs = mTimestep;
}

void SignalTimestep::simulateOneTimestep()
{
    *mpTs = mTimestep;
}

TLMHUB_REGISTER_COMPONENT(SignalTimestep, "Signal")

} // namespace tlmhub
