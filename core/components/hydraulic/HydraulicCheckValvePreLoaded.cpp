#include "core/components/hydraulic/HydraulicCheckValvePreLoaded.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicCheckValvePreLoaded::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    addInputVariable("K_s", "Turbulent restrictor coefficient", "", 5e-7, &mpKs);
    addInputVariable("F_s", "Spring pre-load expressed as pressure", "Pa", 0.0, &mpFs);
    addOutputVariable("x", "Open (1) or closed (0), for animation", "", 0.0, &mpX);
}

void HydraulicCheckValvePreLoaded::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mQTurb.setFlowCoefficient(*mpKs);
}

void HydraulicCheckValvePreLoaded::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double Fs = *mpFs;
    mQTurb.setFlowCoefficient(*mpKs);

    // Once open, the full c1 - c2 drives the flow (pre-load only gates it).
    double q2 = 0.0;
    double x = 0.0;
    if (c1 > c2 + Fs) {
        q2 = mQTurb.getFlow(c1, c2, Zc1, Zc2);
        x = 1.0;
    }
    double q1 = -q2;
    double p1 = c1 + Zc1 * q1;
    double p2 = c2 + Zc2 * q2;

    bool cavitation = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cavitation = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cavitation = true; }
    if (cavitation) {
        q2 = (c1 > c2 + Fs) ? mQTurb.getFlow(c1, c2, Zc1, Zc2) : 0.0;
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
    *mpX = x;
}

TLMHUB_REGISTER_COMPONENT(HydraulicCheckValvePreLoaded, "Hydraulic")

} // namespace tlmhub
