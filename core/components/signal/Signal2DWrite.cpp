#include "core/components/signal/Signal2DWrite.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Signal2DWrite::configure()
{
    mpP2d = addWritePort("P2d", NodeType::Signal2D, false);
    mpP2d->description = "The two-dimensional signal";
    addInputVariable("in1", "First component", "", 0.0, &mpIn1);
    addInputVariable("in2", "Second component", "", 0.0, &mpIn2);
}

void Signal2DWrite::initialize()
{
    mpV0 = getSafeNodeDataPtr(mpP2d, 0);
    mpV1 = getSafeNodeDataPtr(mpP2d, 1);
    simulateOneTimestep();
}

void Signal2DWrite::simulateOneTimestep()
{
    *mpV0 = *mpIn1;
    *mpV1 = *mpIn2;
}

TLMHUB_REGISTER_COMPONENT(Signal2DWrite, "Signal")

} // namespace tlmhub
