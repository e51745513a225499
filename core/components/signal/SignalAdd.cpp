#include "core/components/signal/SignalAdd.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalAdd::configure()
{
    addInputVariable("in1", "Input 1", "", 0.0, &mpIn1);
    addInputVariable("in2", "Input 2", "", 0.0, &mpIn2);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalAdd::initialize()
{
    simulateOneTimestep();
}

void SignalAdd::simulateOneTimestep()
{
    *mpOut = *mpIn1 + *mpIn2;
}

TLMHUB_REGISTER_COMPONENT(SignalAdd, "Signal")

} // namespace tlmhub
