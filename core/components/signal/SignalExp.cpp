#include "core/components/signal/SignalExp.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalExp::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalExp::initialize()
{
    simulateOneTimestep();
}

void SignalExp::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::exp(x);
}

TLMHUB_REGISTER_COMPONENT(SignalExp, "Signal")

} // namespace tlmhub
