#include "core/components/signal/SignalFloor.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalFloor::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalFloor::initialize()
{
    simulateOneTimestep();
}

void SignalFloor::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::floor(x);
}

TLMHUB_REGISTER_COMPONENT(SignalFloor, "Signal")

} // namespace tlmhub
