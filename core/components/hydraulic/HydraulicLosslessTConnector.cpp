#include "core/components/hydraulic/HydraulicLosslessTConnector.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicLosslessTConnector::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Hydraulic);
}

void HydraulicLosslessTConnector::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_p = getSafeNodeDataPtr(mpP3, NodeHydraulic::Pressure);
    mpP3_q = getSafeNodeDataPtr(mpP3, NodeHydraulic::Flow);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeHydraulic::WaveVariable);
    mpP3_Zc = getSafeNodeDataPtr(mpP3, NodeHydraulic::CharImpedance);

    // The junction pressure divides by every impedance.
    if (*mpP1_Zc == 0.0 || *mpP2_Zc == 0.0 || *mpP3_Zc == 0.0) {
        stopSimulation("HydraulicLosslessTConnector: all connected characteristic impedances must be non-zero.");
    }
}

void HydraulicLosslessTConnector::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double c3 = *mpP3_c, Zc3 = *mpP3_Zc;

    double p = (c1 / Zc1 + c2 / Zc2 + c3 / Zc3) / (1.0 / Zc1 + 1.0 / Zc2 + 1.0 / Zc3);
    // Flows use the unclamped junction pressure.
    const double q1 = (p - c1) / Zc1;
    const double q2 = (p - c2) / Zc2;
    const double q3 = (p - c3) / Zc3;
    if (p < 0.0) p = 0.0;

    *mpP1_p = p;
    *mpP1_q = q1;
    *mpP2_p = p;
    *mpP2_q = q2;
    *mpP3_p = p;
    *mpP3_q = q3;
}

TLMHUB_REGISTER_COMPONENT(HydraulicLosslessTConnector, "Hydraulic")

} // namespace tlmhub
