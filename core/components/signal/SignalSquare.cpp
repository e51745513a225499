#include "core/components/signal/SignalSquare.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalSquare::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalSquare::initialize()
{
    simulateOneTimestep();
}

void SignalSquare::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = x * x;
}

TLMHUB_REGISTER_COMPONENT(SignalSquare, "Signal")

} // namespace tlmhub
