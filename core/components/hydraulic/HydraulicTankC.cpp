#include "core/components/hydraulic/HydraulicTankC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicTankC::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addConstant("p", "Default pressure", "Pa", 1.0e5, mP);

    setDefaultStartValue(mpP1, NodeHydraulic::Flow, 0.0);
    disableStartValue(mpP1, NodeHydraulic::Pressure);
    disableStartValue(mpP1, NodeHydraulic::WaveVariable);
    disableStartValue(mpP1, NodeHydraulic::CharImpedance);
}

void HydraulicTankC::initialize()
{
    // Written once; the time step leaves the node untouched.
    *getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure) = mP;
    *getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable) = mP;
    *getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance) = 0.0;
}

TLMHUB_REGISTER_COMPONENT(HydraulicTankC, "Hydraulic")

} // namespace tlmhub
