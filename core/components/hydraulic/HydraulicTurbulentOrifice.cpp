#include "core/components/hydraulic/HydraulicTurbulentOrifice.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void HydraulicTurbulentOrifice::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    addInputVariable("A", "Orifice area", "m^2", 0.00001, &mpA);
    addInputVariable("C_q", "Flow coefficient", "", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
}

void HydraulicTurbulentOrifice::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    // p and q are written once from the initial c/Zc.
    simulateOneTimestep();
}

void HydraulicTurbulentOrifice::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double A = std::fabs(*mpA);
    const double Cq = *mpCq;
    const double rho = *mpRho;

    const double Ks = Cq * A * std::sqrt(2.0 / rho);
    mQTurb.setFlowCoefficient(Ks);

    double q2 = mQTurb.getFlow(c1, c2, Zc1, Zc2);
    double q1 = -q2;
    double p1 = c1 + Zc1 * q1;
    double p2 = c2 + Zc2 * q2;

    // Cavitation: recompute with the vapour side clamped to zero pressure.
    bool cavitation = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cavitation = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cavitation = true; }
    if (cavitation) {
        q2 = mQTurb.getFlow(c1, c2, Zc1, Zc2);
        q1 = -q2;
        p1 = c1 + Zc1 * q1;
        p2 = c2 + Zc2 * q2;
        if (p1 < 0.0) p1 = 0.0;
        if (p2 < 0.0) p2 = 0.0;
    }

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
}

TLMHUB_REGISTER_COMPONENT(HydraulicTurbulentOrifice, "Hydraulic")

} // namespace tlmhub
