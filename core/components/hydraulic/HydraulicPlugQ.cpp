#include "core/components/hydraulic/HydraulicPlugQ.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicPlugQ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
}

void HydraulicPlugQ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    simulateOneTimestep();
}

void HydraulicPlugQ::simulateOneTimestep()
{
    const double q = 0.0;
    double p = *mpP1_c + q * (*mpP1_Zc);
    if (p < 0.0) p = 0.0;
    *mpP1_p = p;
    *mpP1_q = q;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPlugQ, "Hydraulic")

} // namespace tlmhub
