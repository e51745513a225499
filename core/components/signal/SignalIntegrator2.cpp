#include "core/components/signal/SignalIntegrator2.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalIntegrator2::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
}

void SignalIntegrator2::initialize()
{
    mIntegrator.initialize(mTimestep, *mpIn, *mpOut);
}

void SignalIntegrator2::simulateOneTimestep()
{
    *mpOut = mIntegrator.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalIntegrator2, "Signal")

} // namespace tlmhub
