#include "core/components/hydraulic/HydraulicVariableDisplacementPump.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicVariableDisplacementPump::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addInputVariable("eps", "Displacement setting", "-", 1.0, &mpEps);
    addInputVariable("omega_p", "Angular velocity", "rad/s", 50.0, &mpN);
    addInputVariable("D_p", "Displacement", "m^3/rev", 5.0e-5, &mpDp);
    addInputVariable("K_cp", "Leakage coefficient", "m^3/(s Pa)", 1.0e-12, &mpKcp);
    addOutputVariable("a", "Angle", "rad", 0.0, &mpA);
}

void HydraulicVariableDisplacementPump::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    // The angle output keeps its start value.
}

void HydraulicVariableDisplacementPump::simulateOneTimestep()
{
    const double eps = *mpEps, n = *mpN, dp = *mpDp, Kcp = *mpKcp;
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;

    double q2 = (dp * n * eps / (2.0 * pi) + Kcp * (c1 - c2)) / ((Zc1 + Zc2) * Kcp + 1.0);
    // Infinite/NaN bounds from zero impedances are ignored by fmin/fmax.
    q2 = std::fmin(std::fmax(q2, -c2 / Zc2), c1 / Zc1);
    const double q1 = -q2;
    const double p2 = c2 + Zc2 * q2;
    const double p1 = c1 + Zc1 * q1;

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpA = *mpA + n * mTimestep;
}

TLMHUB_REGISTER_COMPONENT(HydraulicVariableDisplacementPump, "Hydraulic")

} // namespace tlmhub
