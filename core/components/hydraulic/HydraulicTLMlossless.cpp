#include "core/components/hydraulic/HydraulicTLMlossless.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicTLMlossless::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    addInputVariable("alpha", "Low pass coefficient", "", 0.0, &mpAlpha);
    addInputVariable("Z_c", "Characteristic impedance", "Pa s/m^3", 1.0e9, &mpZc);
    addConstant("deltat", "Time delay", "s", 0.1, mTimeDelay);

    disableStartValue(mpP1, NodeHydraulic::WaveVariable);
    disableStartValue(mpP1, NodeHydraulic::CharImpedance);
    disableStartValue(mpP2, NodeHydraulic::WaveVariable);
    disableStartValue(mpP2, NodeHydraulic::CharImpedance);
}

void HydraulicTLMlossless::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    const double Zc = *mpZc;
    const double p1s = getDefaultStartValue(mpP1, NodeHydraulic::Pressure);
    const double q1s = getDefaultStartValue(mpP1, NodeHydraulic::Flow);
    const double p2s = getDefaultStartValue(mpP2, NodeHydraulic::Pressure);
    const double q2s = getDefaultStartValue(mpP2, NodeHydraulic::Flow);

    *mpP1_q = q1s;
    *mpP1_p = p1s;
    *mpP1_c = p2s + Zc * q2s;
    *mpP1_Zc = Zc;
    *mpP2_q = q2s;
    *mpP2_p = p2s;
    *mpP2_c = p1s + Zc * q1s;
    *mpP2_Zc = Zc;

    if (mTimeDelay - mTimestep < 0.0) {
        addWarningMessage("The time delay must be at least one time step (deltat >= Ts).");
    }
    // The C/Q ordering adds one step on top of the buffer.
    mDelayedC1.initialize(mTimeDelay - mTimestep, mTimestep, *mpP1_c);
    mDelayedC2.initialize(mTimeDelay - mTimestep, mTimestep, *mpP2_c);
}

void HydraulicTLMlossless::simulateOneTimestep()
{
    const double p1 = *mpP1_p, q1 = *mpP1_q;
    const double p2 = *mpP2_p, q2 = *mpP2_q;
    double c1 = *mpP1_c;
    double c2 = *mpP2_c;
    const double alpha = *mpAlpha;
    const double Zc = *mpZc;

    // Incident waves from p + Zc*q; the filter mixes with the delayed node value.
    const double c10 = p2 + Zc * q2;
    const double c20 = p1 + Zc * q1;
    c1 = alpha * c1 + (1.0 - alpha) * c10;
    c2 = alpha * c2 + (1.0 - alpha) * c20;

    *mpP1_c = mDelayedC1.update(c1);
    *mpP1_Zc = Zc;
    *mpP2_c = mDelayedC2.update(c2);
    *mpP2_Zc = Zc;
}

TLMHUB_REGISTER_COMPONENT(HydraulicTLMlossless, "Hydraulic")

} // namespace tlmhub
