#include "core/components/signal/SignalTan.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalTan::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalTan::initialize()
{
    simulateOneTimestep();
}

void SignalTan::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::tan(x);
}

TLMHUB_REGISTER_COMPONENT(SignalTan, "Signal")

} // namespace tlmhub
