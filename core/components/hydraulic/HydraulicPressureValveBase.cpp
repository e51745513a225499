#include "core/components/hydraulic/HydraulicPressureValveBase.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicPressureValveBase::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addInputVariable("p_ref", "Reference Opening Pressure", "Pa", 2e6, &mpPref);
    addInputVariable("p_h", "Hysteresis Width", "Pa", 5e5, &mpPh);
    addOutputVariable("xv", "Equivalent spool position", "", &mpXv);

    addConstant("tao", "Time Constant of Spool", "s", 0.01, mTao);
    addConstant("k_cs", "Steady State Characteristic due to Spring", "m^3/(s Pa)", 1e-8, mKcs);
    addConstant("k_cf", "Steady State Characteristic due to Flow Forces", "m^3/(s Pa)", 1e-8, mKcf);
    addConstant("q_nom", "Flow with Fully Open Valve and pressure drop Pnom", "m^3/s", 0.001, mQnom);
}

void HydraulicPressureValveBase::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    mCs = std::sqrt(kPnom) / mKcs;
    mCf = 1.0 / (mKcf * std::sqrt(kPnom));
    mPrevX0 = 0.0;

    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, mTao};
    mFilter.initialize(mTimestep, num, den, 0.0, 0.0, 0.0, mQnom / std::sqrt(kPnom));
}

void HydraulicPressureValveBase::simulateOneTimestep()
{
    // The spool balance uses the node pressures of the previous step.
    double p1 = *mpP1_p, c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double p2 = *mpP2_p, c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double pref = *mpPref, ph = *mpPh;

    // Spring stiffness plus the flow-force stiffening, the latter only for p1 > p2.
    const double b1 = (p1 - p2) * mCf < 0.0 ? mCs : mCs + (p1 - p2) * mCf;
    const double s = std::sqrt(std::fabs(p1 - p2));
    const double denom = 2.0 * s + (Zc1 + Zc2) * mPrevX0;
    const double gamma = denom != 0.0 ? 2.0 * s / denom : 1.0;
    const double b2 = std::max(gamma * (Zc1 + Zc2) * s, 0.0);

    const double xs = (openingPressure(gamma, c1, c2, pref) + b2 * mPrevX0 / 2.0) / (b1 + b2);
    const double xsh = mHyst.getValue(xs, ph / (b1 + b2), mPrevX0);

    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, mTao / (1.0 + b2 / b1)};
    mFilter.setNumDen(num, den);
    double x0 = mFilter.update(xsh);

    mTurb.setFlowCoefficient(x0);
    double q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
    double q1 = -q2;
    p2 = c2 + Zc2 * q2;
    p1 = c1 + Zc1 * q1;

    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) {
        // The spool is not re-evaluated: the retry reuses the filter output.
        x0 = mFilter.value();
        mTurb.setFlowCoefficient(x0);
        q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
        q1 = -q2;
        p2 = std::max(c2 + Zc2 * q2, 0.0);
        p1 = std::max(c1 + Zc1 * q1, 0.0);
    }

    mPrevX0 = x0;
    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpXv = x0;
}

} // namespace tlmhub
