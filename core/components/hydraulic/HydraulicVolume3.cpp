#include "core/components/hydraulic/HydraulicVolume3.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicVolume3::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Hydraulic);
    addConstant("V", "Volume", "m^3", 1.0e-3, mVolume);
    addConstant("Beta_e", "Bulkmodulus", "Pa", 1.0e9, mBetae);
    addConstant("alpha", "Low pass coefficient to dampen standing delayline waves", "", 0.1, mAlpha);
    for (Port* p : {mpP1, mpP2, mpP3}) {
        setDefaultStartValue(p, NodeHydraulic::Flow, 0.0);
        setDefaultStartValue(p, NodeHydraulic::Pressure, 1.0e5);
    }
}

void HydraulicVolume3::initialize()
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

    // Hopsan quirk: the source's leading factor 3/2 is integer division (= 1).
    mZc = mBetae / mVolume * mTimestep / (1.0 - mAlpha);

    const double q1 = *mpP1_q, p1 = *mpP1_p;
    const double q2 = *mpP2_q, p2 = *mpP2_p;
    const double q3 = *mpP3_q, p3 = *mpP3_p;
    const double Zc = mZc;
    const double pMean = ((p1 + Zc * q1) + (p2 + Zc * q2) + (p3 + Zc * q3)) / 3.0;
    // Reproduced as specified (reference: "as written").
    *mpP1_c = pMean - p1 - Zc * q1;
    *mpP2_c = pMean - p2 - Zc * q2;
    *mpP3_c = pMean - p3 - Zc * q3;
    *mpP1_Zc = Zc;
    *mpP2_Zc = Zc;
    *mpP3_Zc = Zc;
}

void HydraulicVolume3::simulateOneTimestep()
{
    const double q1 = *mpP1_q, c1 = *mpP1_c;
    const double q2 = *mpP2_q, c2 = *mpP2_c;
    const double q3 = *mpP3_q, c3 = *mpP3_c;
    // Hopsan quirk: port 1 uses port 2's impedance.
    const double Zc1 = *mpP2_Zc, Zc2 = *mpP2_Zc, Zc3 = *mpP3_Zc;
    const double alpha = mAlpha;

    const double pMean = ((c1 + Zc1 * 2.0 * q1) + (c2 + Zc2 * 2.0 * q2) + (c3 + Zc3 * 2.0 * q3)) / 3.0;
    const double c10 = pMean * 2.0 - c1 - 2.0 * Zc1 * q1;
    const double c20 = pMean * 2.0 - c2 - 2.0 * Zc2 * q2;
    const double c30 = pMean * 2.0 - c3 - 2.0 * Zc3 * q3;

    *mpP1_c = alpha * c1 + (1.0 - alpha) * c10 + (Zc1 - mZc) * q1;
    *mpP2_c = alpha * c2 + (1.0 - alpha) * c20 + (Zc2 - mZc) * q2;
    *mpP3_c = alpha * c3 + (1.0 - alpha) * c30 + (Zc3 - mZc) * q3;
    *mpP1_Zc = mZc;
    *mpP2_Zc = mZc;
    *mpP3_Zc = mZc;
}

TLMHUB_REGISTER_COMPONENT(HydraulicVolume3, "Hydraulic")

} // namespace tlmhub
