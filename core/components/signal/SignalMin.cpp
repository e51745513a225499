#include "core/components/signal/SignalMin.h"

#include "core/ComponentFactory.h"

#include <vector>

namespace tlmhub {

void SignalMin::configure()
{
    mpIn = addReadMultiPort("in", NodeType::Signal, false);
    addOutputVariable("out", "Minimum of the inputs", "", &mpOut);
}

void SignalMin::initialize()
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

void SignalMin::simulateOneTimestep()
{
    double m = *mIn[0];
    for (std::size_t i = 1; i < mIn.size(); ++i) {
        if (*mIn[i] < m) {
            m = *mIn[i];
        }
    }
    *mpOut = m;
}

TLMHUB_REGISTER_COMPONENT(SignalMin, "Signal")

} // namespace tlmhub
