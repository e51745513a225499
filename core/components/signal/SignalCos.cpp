#include "core/components/signal/SignalCos.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalCos::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalCos::initialize()
{
    simulateOneTimestep();
}

void SignalCos::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::cos(x);
}

TLMHUB_REGISTER_COMPONENT(SignalCos, "Signal")

} // namespace tlmhub
