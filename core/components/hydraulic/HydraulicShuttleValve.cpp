#include "core/components/hydraulic/HydraulicShuttleValve.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicShuttleValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Hydraulic);
    addOutputVariable("out", "Open side: -1 = P1, 1 = P2", "", &mpOut);
}

void HydraulicShuttleValve::initialize()
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
}

void HydraulicShuttleValve::simulateOneTimestep()
{
    // Switching uses the pressures of the previous step.
    double p1 = *mpP1_p, p2 = *mpP2_p;
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double c3 = *mpP3_c, Zc3 = *mpP3_Zc;

    double q1, q2, q3;
    if (p1 > p2) {
        q3 = (c1 - c3) / (Zc1 + Zc3);
        q1 = -q3;
        q2 = 0.0;
        *mpOut = -1.0;
    } else {
        q3 = (c2 - c3) / (Zc2 + Zc3);
        q2 = -q3;
        q1 = 0.0;
        *mpOut = 1.0;
    }

    p1 = c1 + q1 * Zc1;
    p2 = c2 + q2 * Zc2;
    double p3 = c3 + q3 * Zc3;
    if (p1 < 0.0) { p1 = 0.0; }
    if (p2 < 0.0) { p2 = 0.0; }
    if (p3 < 0.0) { p3 = 0.0; }

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP3_p = p3;
    *mpP3_q = q3;
}

TLMHUB_REGISTER_COMPONENT(HydraulicShuttleValve, "Hydraulic")

} // namespace tlmhub
