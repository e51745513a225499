#include "core/components/other/HydraulicDummyC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicDummyC::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic, false);
    addInputVariable("in", "Loop length", "", 0.0, &mpIn);
}

void HydraulicDummyC::initialize()
{
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
}

void HydraulicDummyC::simulateOneTimestep()
{
    // The loop length is the point (CPU load); the product is 0 for in > 0.
    const double n = *mpIn;
    double c = 1.0;
    for (int i = 0; i < n; ++i) { c = c * i; }
    *mpP1_c = c;
}

TLMHUB_REGISTER_COMPONENT(HydraulicDummyC, "Other")

} // namespace tlmhub
