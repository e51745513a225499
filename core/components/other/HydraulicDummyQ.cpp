#include "core/components/other/HydraulicDummyQ.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicDummyQ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic, false);
    addInputVariable("in", "Loop length", "", 0.0, &mpIn);
}

void HydraulicDummyQ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
}

void HydraulicDummyQ::simulateOneTimestep()
{
    // The loop length is the point (CPU load); the product is 0 for in > 0.
    const double n = *mpIn;
    double p = 1.0;
    for (int i = 0; i < n; ++i) { p = p * i; }
    *mpP1_p = p;
}

TLMHUB_REGISTER_COMPONENT(HydraulicDummyQ, "Other")

} // namespace tlmhub
