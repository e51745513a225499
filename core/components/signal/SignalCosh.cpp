#include "core/components/signal/SignalCosh.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalCosh::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalCosh::initialize()
{
    simulateOneTimestep();
}

void SignalCosh::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::cosh(x);
}

TLMHUB_REGISTER_COMPONENT(SignalCosh, "Signal")

} // namespace tlmhub
