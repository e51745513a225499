#include "core/components/signal/Signal2DWriteRead.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Signal2DWriteRead::configure()
{
    mpP2d = addBiDirectionalSignalPort("P2d", NodeType::Signal2D, false);
    mpP2d->description = "The two dimensional signal port";
    // This end produces v0: the partner that reads it is sorted after this component.
    mpP2d->sortHint = SortHint::Source;
    // Hopsan's names are from the node's point of view: "write" is the input this component
    // writes into the node, "read" the output it reads from it.
    addInputVariable("write", "", "", 0.0, &mpWrite);
    addOutputVariable("read", "", "", 0.0, &mpRead);
}

void Signal2DWriteRead::initialize()
{
    mpV0 = getSafeNodeDataPtr(mpP2d, 0);
    mpV1 = getSafeNodeDataPtr(mpP2d, 1);
    simulateOneTimestep();
}

void Signal2DWriteRead::simulateOneTimestep()
{
    *mpV0 = *mpWrite;
    *mpRead = *mpV1;
}

TLMHUB_REGISTER_COMPONENT(Signal2DWriteRead, "Signal")

} // namespace tlmhub
