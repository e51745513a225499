#include "core/components/hydraulic/HydraulicPilotControlledCheckValve.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicPilotControlledCheckValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPilot = addPowerPort("P_PILOT", NodeType::Hydraulic);
    addInputVariable("phi", "Pilot area ratio", "", 3.5, &mpPhi);
    addInputVariable("p_f", "Cracking (opening) pressure", "Pa", 1e5, &mpPf);
    addConstant("K_s", "Turbulent restrictor coefficient", "", 5e-7, mKs);
    addOutputVariable("x", "Open (1) or closed (0), for animation", "", 0.0, &mpX);
}

void HydraulicPilotControlledCheckValve::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPilot_p = getSafeNodeDataPtr(mpPilot, NodeHydraulic::Pressure);
    mpPilot_c = getSafeNodeDataPtr(mpPilot, NodeHydraulic::WaveVariable);
    mQTurb.setFlowCoefficient(mKs);
}

void HydraulicPilotControlledCheckValve::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    double cPilot = *mpPilot_c;
    const double phi = *mpPhi;
    const double pf = *mpPf;

    double q2 = 0.0;
    double x = 0.0;
    if (c1 + cPilot * phi - c2 > pf) {
        q2 = mQTurb.getFlow(c1, c2, Zc1, Zc2);
        x = 1.0;
    }
    double q1 = -q2;
    double p1 = c1 + Zc1 * q1;
    double p2 = c2 + Zc2 * q2;
    double pPilot = cPilot;

    bool cavitation = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cavitation = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cavitation = true; }
    if (pPilot < 0.0) { cPilot = 0.0; cavitation = true; }
    if (cavitation) {
        // Reference quirk: the retry opens on plain c1 > c2.
        q2 = (c1 > c2) ? mQTurb.getFlow(c1, c2, Zc1, Zc2) : 0.0;
        q1 = -q2;
        p1 = c1 + Zc1 * q1;
        p2 = c2 + Zc2 * q2;
        pPilot = cPilot;
        if (p1 < 0.0) p1 = 0.0;
        if (p2 < 0.0) p2 = 0.0;
    }

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpPilot_p = pPilot;
    *mpX = x;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPilotControlledCheckValve, "Hydraulic")

} // namespace tlmhub
