#include "core/components/signal/Signal2DSplit.h"

#include "core/ComponentFactory.h"

#include <algorithm>

namespace tlmhub {

namespace {

// One dimension's direction. A scalar port directly connected to a write port makes the
// scalar side the producer: it feeds its slot of the 2D node; otherwise the slot feeds it.
// Only direct connections count, as in Hopsan (a writer behind a system port does not).
void routeDimension(const Port* scalarPort, double* scalar, double* slot, double*& from, double*& to)
{
    const bool scalarIsWritten = std::any_of(scalarPort->connectedPorts.begin(), scalarPort->connectedPorts.end(),
                                             [](const Port* other) { return other->kind() == PortKind::Write; });
    from = scalarIsWritten ? scalar : slot;
    to = scalarIsWritten ? slot : scalar;
}

} // namespace

void Signal2DSplit::configure()
{
    mpP2d = addBiDirectionalSignalPort("P2d", NodeType::Signal2D, false);
    mpP2d->description = "The two dimensional signal port";
    mpV1 = addBiDirectionalSignalPort("v1", NodeType::Signal, false);
    mpV1->description = "The first dimension";
    mpV2 = addBiDirectionalSignalPort("v2", NodeType::Signal, false);
    mpV2->description = "The second dimension";
}

void Signal2DSplit::initialize()
{
    routeDimension(mpV1, getSafeNodeDataPtr(mpV1, NodeSignal::Value), getSafeNodeDataPtr(mpP2d, 0), mpFrom1, mpTo1);
    routeDimension(mpV2, getSafeNodeDataPtr(mpV2, NodeSignal::Value), getSafeNodeDataPtr(mpP2d, 1), mpFrom2, mpTo2);
    simulateOneTimestep();
}

void Signal2DSplit::simulateOneTimestep()
{
    *mpTo1 = *mpFrom1;
    *mpTo2 = *mpFrom2;
}

TLMHUB_REGISTER_COMPONENT(Signal2DSplit, "Signal")

} // namespace tlmhub
