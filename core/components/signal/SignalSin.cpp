#include "core/components/signal/SignalSin.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalSin::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalSin::initialize()
{
    simulateOneTimestep();
}

void SignalSin::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::sin(x);
}

TLMHUB_REGISTER_COMPONENT(SignalSin, "Signal")

} // namespace tlmhub
