#include "core/components/hydraulic/HydraulicPressureSourceQ.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicPressureSourceQ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("p", "Set pressure", "Pa", 1e5, &mpIn);
}

void HydraulicPressureSourceQ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
}

void HydraulicPressureSourceQ::simulateOneTimestep()
{
    const double p = *mpIn;
    // No guard for Zc == 0 and no pressure floor, as in the reference.
    const double q = (p - *mpP1_c) / (*mpP1_Zc);
    *mpP1_p = p;
    *mpP1_q = q;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureSourceQ, "Hydraulic")

} // namespace tlmhub
