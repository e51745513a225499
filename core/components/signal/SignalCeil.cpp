#include "core/components/signal/SignalCeil.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalCeil::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalCeil::initialize()
{
    simulateOneTimestep();
}

void SignalCeil::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::ceil(x);
}

TLMHUB_REGISTER_COMPONENT(SignalCeil, "Signal")

} // namespace tlmhub
