#include "core/components/signal/Signal2DSplit.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

namespace {

// Whether a port directly connected to `port` is a write port: the scalar side is then
// the producer. Only direct connections count, as in Hopsan (a writer behind a system
// port does not).
bool fedByWritePort(const Port* port)
{
    for (const Port* other : port->connectedPorts)
        if (other->kind() == PortKind::Write) return true;
    return false;
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
    double* slot0 = getSafeNodeDataPtr(mpP2d, 0);
    double* slot1 = getSafeNodeDataPtr(mpP2d, 1);
    double* v1 = getSafeNodeDataPtr(mpV1, NodeSignal::Value);
    double* v2 = getSafeNodeDataPtr(mpV2, NodeSignal::Value);
    if (fedByWritePort(mpV1)) {
        mpFrom1 = v1;
        mpTo1 = slot0;
    } else {
        mpFrom1 = slot0;
        mpTo1 = v1;
    }
    if (fedByWritePort(mpV2)) {
        mpFrom2 = v2;
        mpTo2 = slot1;
    } else {
        mpFrom2 = slot1;
        mpTo2 = v2;
    }
    simulateOneTimestep();
}

void Signal2DSplit::simulateOneTimestep()
{
    *mpTo1 = *mpFrom1;
    *mpTo2 = *mpFrom2;
}

TLMHUB_REGISTER_COMPONENT(Signal2DSplit, "Signal")

} // namespace tlmhub
