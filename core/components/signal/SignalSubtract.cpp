#include "core/components/signal/SignalSubtract.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalSubtract::configure()
{
    addInputVariable("in1", "Input 1", "", 0.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 0.0, &mpIn2);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalSubtract::initialize()
{
    simulateOneTimestep();
}

void SignalSubtract::simulateOneTimestep()
{
    *mpOut = *mpIn1 - *mpIn2;
}

TLMHUB_REGISTER_COMPONENT(SignalSubtract, "Signal")

} // namespace tlmhub
