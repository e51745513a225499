#include "core/components/signal/SignalSinh.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalSinh::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalSinh::initialize()
{
    simulateOneTimestep();
}

void SignalSinh::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::sinh(x);
}

TLMHUB_REGISTER_COMPONENT(SignalSinh, "Signal")

} // namespace tlmhub
