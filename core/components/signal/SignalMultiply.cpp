#include "core/components/signal/SignalMultiply.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalMultiply::configure()
{
    addInputVariable("in1", "Input 1", "", 1.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 1.0, &mpIn2);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalMultiply::initialize()
{
    simulateOneTimestep();
}

void SignalMultiply::simulateOneTimestep()
{
    *mpOut = *mpIn1 * *mpIn2;
}

TLMHUB_REGISTER_COMPONENT(SignalMultiply, "Signal")

} // namespace tlmhub
