#include "core/components/hydraulic/HydraulicVolume.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicVolume::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    addInputVariable("alpha", "Low pass coefficient to dampen standing waves", "", 0.1, &mpAlpha);
    addConstant("V", "Volume", "m^3", 1.0e-3, mV);
    addConstant("Beta_e", "Bulkmodulus", "Pa", 1.0e9, mBetae);
    addConstant("P_high", "High pressure (for animation)", "Pa", 2e7, mPhigh);

    setDefaultStartValue(mpP1, NodeHydraulic::Flow, 0.0);
    setDefaultStartValue(mpP1, NodeHydraulic::Pressure, 1.0e5);
    setDefaultStartValue(mpP2, NodeHydraulic::Flow, 0.0);
    setDefaultStartValue(mpP2, NodeHydraulic::Pressure, 1.0e5);
    disableStartValue(mpP1, NodeHydraulic::WaveVariable);
    disableStartValue(mpP1, NodeHydraulic::CharImpedance);
    disableStartValue(mpP2, NodeHydraulic::WaveVariable);
    disableStartValue(mpP2, NodeHydraulic::CharImpedance);
}

void HydraulicVolume::initialize()
{
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    // Impedance is fixed here with the initial alpha (later alpha changes only
    // affect the filter weight).
    const double alpha = *mpAlpha;
    mZc = mBetae / mV * mTimestep / (1.0 - alpha);

    // Seeding uses a single Zc, not 2*Zc.
    *mpP1_c = getDefaultStartValue(mpP2, NodeHydraulic::Pressure)
              + mZc * getDefaultStartValue(mpP2, NodeHydraulic::Flow);
    *mpP1_Zc = mZc;
    *mpP2_c = getDefaultStartValue(mpP1, NodeHydraulic::Pressure)
              + mZc * getDefaultStartValue(mpP1, NodeHydraulic::Flow);
    *mpP2_Zc = mZc;
}

void HydraulicVolume::simulateOneTimestep()
{
    const double q1 = *mpP1_q;
    const double q2 = *mpP2_q;
    double c1 = *mpP1_c;
    double c2 = *mpP2_c;
    const double alpha = *mpAlpha;

    // Both incident waves are formed before either wave variable is replaced.
    const double c10 = c2 + 2.0 * mZc * q2;
    const double c20 = c1 + 2.0 * mZc * q1;
    c1 = alpha * c1 + (1.0 - alpha) * c10;
    c2 = alpha * c2 + (1.0 - alpha) * c20;

    *mpP1_c = c1;
    *mpP1_Zc = mZc;
    *mpP2_c = c2;
    *mpP2_Zc = mZc;
}

TLMHUB_REGISTER_COMPONENT(HydraulicVolume, "Hydraulic")

} // namespace tlmhub
