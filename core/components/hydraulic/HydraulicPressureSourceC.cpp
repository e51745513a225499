#include "core/components/hydraulic/HydraulicPressureSourceC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicPressureSourceC::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("p", "Set pressure", "Pa", 1.0e5, &mpIn);

    setDefaultStartValue(mpP1, NodeHydraulic::Flow, 0.0);
    disableStartValue(mpP1, NodeHydraulic::Pressure);
    disableStartValue(mpP1, NodeHydraulic::WaveVariable);
    disableStartValue(mpP1, NodeHydraulic::CharImpedance);
}

void HydraulicPressureSourceC::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);

    *mpP1_p = *mpIn;
    simulateOneTimestep();
}

void HydraulicPressureSourceC::simulateOneTimestep()
{
    // Pressure itself is produced by the Q-side as p = c + 0*q.
    *mpP1_c = *mpIn;
    *mpP1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureSourceC, "Hydraulic")

} // namespace tlmhub
