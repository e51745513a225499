#include "core/components/signal/SignalSign.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalSign::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
}

void SignalSign::initialize()
{
    simulateOneTimestep();
}

void SignalSign::simulateOneTimestep()
{
    const double x = *mpIn;
    *mpOut = sign(x);
}

TLMHUB_REGISTER_COMPONENT(SignalSign, "Signal")

} // namespace tlmhub
