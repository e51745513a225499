#include "core/components/signal/SignalDummy.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalDummy::configure()
{
    addInputVariable("in", "Loop length", "", 0.0, &mpIn);
    addOutputVariable("out", "Dummy output", "", &mpOut);
}

void SignalDummy::simulateOneTimestep()
{
    // The loop length is the point (CPU load); the product is 0 for in > 0.
    const double n = *mpIn;
    double out = 1.0;
    for (int i = 0; i < n; ++i) { out = out * i; }
    *mpOut = out;
}

TLMHUB_REGISTER_COMPONENT(SignalDummy, "Other")

} // namespace tlmhub
