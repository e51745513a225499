#include "core/components/signal/Signal2DReadWrite.h"

#include "core/ComponentFactory.h"
#include "core/ParameterEvaluator.h"

namespace tlmhub {

void Signal2DReadWrite::configure()
{
    mpP2d = addBiDirectionalSignalPort("P2d", NodeType::Signal2D, false);
    mpP2d->description = "The two dimensional signal port";
    mpP2d->sortHint = SortHint::Destination;
    addConditionalConstant("sh2d", "2D Port sort hint", {"Destination", "IndependentDestination"}, 0,
                           mSortHintChoice);
    // Named from the node's point of view, as in Hopsan: "read" is the output holding v0,
    // "write" the input that goes into v1.
    addOutputVariable("read", "", "", 0.0, &mpRead);
    Port* write = addInputVariable("write", "", "", 0.0, &mpWrite);
    write->sortHint = SortHint::IndependentDestination;
}

void Signal2DReadWrite::preInitialize()
{
    // The sort runs before the general parameter evaluation of this initialise, so sh2d is
    // evaluated here to sort by its current value (a failure is reported by that
    // evaluation, which comes next).
    if (Parameter* sh2d = parameters().find("sh2d")) (void)ParameterEvaluator::evaluate(*this, *sh2d);
    mpP2d->sortHint = mSortHintChoice == 1 ? SortHint::IndependentDestination : SortHint::Destination;
}

void Signal2DReadWrite::initialize()
{
    mpV0 = getSafeNodeDataPtr(mpP2d, 0);
    mpV1 = getSafeNodeDataPtr(mpP2d, 1);
    simulateOneTimestep();
}

void Signal2DReadWrite::simulateOneTimestep()
{
    *mpRead = *mpV0;
    *mpV1 = *mpWrite;
}

TLMHUB_REGISTER_COMPONENT(Signal2DReadWrite, "Signal")

} // namespace tlmhub
