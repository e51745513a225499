#include "core/components/signal/SignalPower.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalPower::configure()
{
    addInputVariable("in", "Base (its absolute value is used)", "", 0.0, &mpIn);
    addInputVariable("x", "Exponent", "", 0.0, &mpX);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalPower::initialize()
{
    simulateOneTimestep();
}

void SignalPower::simulateOneTimestep()
{
    *mpOut = std::pow(std::fabs(*mpIn), *mpX);
}

TLMHUB_REGISTER_COMPONENT(SignalPower, "Signal")

} // namespace tlmhub
