#include "core/components/signal/SignalTanh.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void SignalTanh::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalTanh::initialize()
{
    simulateOneTimestep();
}

void SignalTanh::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = std::tanh(x);
}

TLMHUB_REGISTER_COMPONENT(SignalTanh, "Signal")

} // namespace tlmhub
