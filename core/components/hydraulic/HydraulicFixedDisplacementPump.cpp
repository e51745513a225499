#include "core/components/hydraulic/HydraulicFixedDisplacementPump.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicFixedDisplacementPump::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addInputVariable("n_p", "Angular velocity", "rad/s", 250.0, &mpN);
    addInputVariable("D_p", "Displacement", "m^3/rev", 5.0e-5, &mpDp);
    addInputVariable("C_lp", "Leakage coefficient", "m^3/(s Pa)", 1.0e-12, &mpClp);
    addOutputVariable("a", "Angle", "rad", 0.0, &mpA);
}

void HydraulicFixedDisplacementPump::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    // The shaft angle always starts at zero, whatever a#Value says.
    *mpA = 0.0;
}

void HydraulicFixedDisplacementPump::simulateOneTimestep()
{
    const double n = *mpN, dp = *mpDp, Clp = *mpClp;
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;

    double q2 = (dp * n / (2.0 * pi) + Clp * (c1 - c2)) / ((Zc1 + Zc2) * Clp + 1.0);
    // On a zero-impedance node c/Zc is +-inf or NaN; fmin/fmax then ignore that
    // bound, which is the intended behaviour.
    q2 = std::fmin(std::fmax(q2, -c2 / Zc2), c1 / Zc1);
    double q1 = -q2;
    double p2 = c2 + Zc2 * q2;
    double p1 = c1 + Zc1 * q1;

    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) {
        q2 = (dp * n / (2.0 * pi) + Clp * (c1 - c2)) / ((Zc1 + Zc2) * Clp + 1.0);
        p1 = c1 + Zc1 * q1; // the old q1 on purpose (reference quirk)
        p2 = c2 + Zc2 * q2;
        if (p1 <= 0.0) {
            p1 = 0.0;
            q2 = std::min(q2, 0.0);
        }
        if (p2 <= 0.0) {
            p2 = 0.0;
            q2 = std::max(q2, 0.0);
        }
        q1 = -q2;
    }

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpA = *mpA + n * mTimestep;
}

TLMHUB_REGISTER_COMPONENT(HydraulicFixedDisplacementPump, "Hydraulic")

} // namespace tlmhub
