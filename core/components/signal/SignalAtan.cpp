#include "core/components/signal/SignalAtan.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalAtan::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalAtan::initialize()
{
    simulateOneTimestep();
}

void SignalAtan::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::atan(x);
}

TLMHUB_REGISTER_COMPONENT(SignalAtan, "Signal")

} // namespace tlmhub
