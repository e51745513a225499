#include "core/components/signal/SignalAbsoluteValue.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalAbsoluteValue::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalAbsoluteValue::initialize()
{
    simulateOneTimestep();
}

void SignalAbsoluteValue::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = (x > 0.0) ? x : -x;
}

TLMHUB_REGISTER_COMPONENT(SignalAbsoluteValue, "Signal")

} // namespace tlmhub
