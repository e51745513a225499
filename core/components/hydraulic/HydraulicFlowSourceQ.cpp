#include "core/components/hydraulic/HydraulicFlowSourceQ.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicFlowSourceQ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("q", "Set flow", "m^3/s", 1.0e-3, &mpIn);
}

void HydraulicFlowSourceQ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    simulateOneTimestep();
}

void HydraulicFlowSourceQ::simulateOneTimestep()
{
    const double q = *mpIn;
    double p = *mpP1_c + q * (*mpP1_Zc);
    if (p < 0.0) p = 0.0;   // cavitation floor
    *mpP1_p = p;
    *mpP1_q = q;
}

TLMHUB_REGISTER_COMPONENT(HydraulicFlowSourceQ, "Hydraulic")

} // namespace tlmhub
