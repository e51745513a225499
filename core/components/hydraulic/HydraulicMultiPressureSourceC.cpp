#include "core/components/hydraulic/HydraulicMultiPressureSourceC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicMultiPressureSourceC::configure()
{
    mpMP = addPowerMultiPort("MP", NodeType::Hydraulic);
    addInputVariable("p", "Set pressure", "Pa", 1.0e5, &mpIn);

    disableStartValue(mpMP, NodeHydraulic::Pressure);
    disableStartValue(mpMP, NodeHydraulic::WaveVariable);
    disableStartValue(mpMP, NodeHydraulic::CharImpedance);
}

void HydraulicMultiPressureSourceC::initialize()
{
    mNumPorts = getNumPorts(mpMP);
    mvpMP_c.resize(mNumPorts);
    mvpMP_Zc.resize(mNumPorts);
    const double p = *mpIn;
    const double q0 = getDefaultStartValue(mpMP, NodeHydraulic::Flow);
    for (std::size_t i = 0; i < mNumPorts; ++i) {
        mvpMP_c[i] = getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::WaveVariable);
        mvpMP_Zc[i] = getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::CharImpedance);
        *getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::Pressure) = p;
        *getSafeMultiPortNodeDataPtr(mpMP, i, NodeHydraulic::Flow) = q0;
        *mvpMP_c[i] = p;
        *mvpMP_Zc[i] = 0.0;
    }
}

void HydraulicMultiPressureSourceC::simulateOneTimestep()
{
    const double p = *mpIn;
    for (std::size_t i = 0; i < mNumPorts; ++i) {
        *mvpMP_c[i] = p;
        *mvpMP_Zc[i] = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(HydraulicMultiPressureSourceC, "Hydraulic")

} // namespace tlmhub
