#include "core/components/signal/Signal2DRead.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Signal2DRead::configure()
{
    // A read port, so that the writer of the node is sorted before this component.
    mpP2d = addReadPort("P2d", NodeType::Signal2D, false);
    mpP2d->description = "The two-dimensional signal";
    addOutputVariable("out1", "First component", "", 0.0, &mpOut1);
    addOutputVariable("out2", "Second component", "", 0.0, &mpOut2);
}

void Signal2DRead::initialize()
{
    mpV0 = getSafeNodeDataPtr(mpP2d, 0);
    mpV1 = getSafeNodeDataPtr(mpP2d, 1);
    simulateOneTimestep();
}

void Signal2DRead::simulateOneTimestep()
{
    *mpOut1 = *mpV0;
    *mpOut2 = *mpV1;
}

TLMHUB_REGISTER_COMPONENT(Signal2DRead, "Signal")

} // namespace tlmhub
