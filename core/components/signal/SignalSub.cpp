#include "core/components/signal/SignalSub.h"

#include "core/ComponentFactory.h"

#include <vector>

namespace tlmhub {

void SignalSub::configure()
{
    mpInSum = addReadMultiPort("insum", NodeType::Signal, false);
    mpInSub = addReadMultiPort("insub", NodeType::Signal, false);
    addOutputVariable("out", "Difference", "", &mpOut);
}

void SignalSub::initialize()
{
    // Bind every sub-port of mpInSum; an unconnected multiport reads one dummy 0.
    mInSum.clear();
    const std::size_t nSum = getNumPorts(mpInSum);
    if (nSum == 0) {
        mInSum.push_back(getSafeNodeDataPtr(mpInSum, NodeSignal::Value));
    } else {
        for (std::size_t i = 0; i < nSum; ++i) {
            mInSum.push_back(getSafeMultiPortNodeDataPtr(mpInSum, i, NodeSignal::Value));
        }
    }
    // Bind every sub-port of mpInSub; an unconnected multiport reads one dummy 0.
    mInSub.clear();
    const std::size_t nSub = getNumPorts(mpInSub);
    if (nSub == 0) {
        mInSub.push_back(getSafeNodeDataPtr(mpInSub, NodeSignal::Value));
    } else {
        for (std::size_t i = 0; i < nSub; ++i) {
            mInSub.push_back(getSafeMultiPortNodeDataPtr(mpInSub, i, NodeSignal::Value));
        }
    }
    simulateOneTimestep();
}

void SignalSub::simulateOneTimestep()
{
    double acc = 0.0;
    for (double* p : mInSum) {
        acc += *p;
    }
    for (double* p : mInSub) {
        acc -= *p;
    }
    *mpOut = acc;
}

TLMHUB_REGISTER_COMPONENT(SignalSub, "Signal")

} // namespace tlmhub
