#include "core/components/hydraulic/HydraulicMultiTankC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicMultiTankC::configure()
{
    mpMP = addPowerMultiPort("MP", NodeType::Hydraulic);
    addConstant("p", "Default pressure", "Pa", 1.0e5, mP);

    disableStartValue(mpMP, NodeHydraulic::Pressure);
    disableStartValue(mpMP, NodeHydraulic::WaveVariable);
    disableStartValue(mpMP, NodeHydraulic::CharImpedance);
}

void HydraulicMultiTankC::initialize()
{
    const std::size_t n = getNumPorts(mpMP);
    const double q0 = getDefaultStartValue(mpMP, NodeHydraulic::Flow);
    // Nodes are written once; nothing changes during the simulation.
    for (std::size_t i = 0; i < n; ++i) {
        *getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::Pressure) = mP;
        *getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::Flow) = q0;
        *getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::WaveVariable) = mP;
        *getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::CharImpedance) = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(HydraulicMultiTankC, "Hydraulic")

} // namespace tlmhub
