#include "core/components/signal/SignalSum.h"

#include "core/ComponentFactory.h"

#include <vector>

namespace tlmhub {

void SignalSum::configure()
{
    mpIn = addReadMultiPort("in", NodeType::Signal, false);
    addOutputVariable("out", "Sum of the inputs", "", &mpOut);
}

void SignalSum::initialize()
{
    // Bind every sub-port of mpIn; an unconnected multiport reads one dummy 0.
    mIn.clear();
    const std::size_t n = getNumPorts(mpIn);
    if (n == 0) {
        mIn.push_back(getSafeNodeDataPtr(mpIn, NodeSignal::Value));
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            mIn.push_back(getSafeMultiPortNodeDataPtr(mpIn, i, NodeSignal::Value));
        }
    }
    simulateOneTimestep();
}

void SignalSum::simulateOneTimestep()
{
    double acc = 0.0;
    for (double* p : mIn) {
        acc += *p;
    }
    *mpOut = acc;
}

TLMHUB_REGISTER_COMPONENT(SignalSum, "Signal")

} // namespace tlmhub
