#include "core/components/hydraulic/HydraulicLosslessConnector.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicLosslessConnector::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
}

void HydraulicLosslessConnector::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    // Two zero-impedance sides would give a division by zero every step.
    if (*mpP1_Zc + *mpP2_Zc == 0.0) {
        stopSimulation("HydraulicLosslessConnector must be connected to at least one capacitive "
                       "component (sum of characteristic impedances is zero).");
    }
}

void HydraulicLosslessConnector::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;

    const double q = (c1 - c2) / (Zc1 + Zc2);
    double p1 = c1 - q * Zc1;
    double p2 = c2 + q * Zc2;
    if (p1 < 0.0) p1 = 0.0;
    if (p2 < 0.0) p2 = 0.0;

    *mpP1_p = p1;
    *mpP1_q = -q;
    *mpP2_p = p2;
    *mpP2_q = q;
}

TLMHUB_REGISTER_COMPONENT(HydraulicLosslessConnector, "Hydraulic")

} // namespace tlmhub
