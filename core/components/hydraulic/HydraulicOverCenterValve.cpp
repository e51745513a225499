#include "core/components/hydraulic/HydraulicOverCenterValve.h"

#include "core/ComponentFactory.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicOverCenterValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPC = addPowerPort("P_CONTROL", NodeType::Hydraulic);

    addInputVariable("p_ref", "Reference opening pressure", "Pa", 2e6, &mpPref);
    addInputVariable("p_h", "Hysteresis width", "Pa", 5e5, &mpPh);
    addInputVariable("a_ratio", "Area ratio", "-", 5.0, &mpAratio);
    addOutputVariable("xv", "Equivalent opening", "", &mpXv);

    addConstant("tao", "Time constant of spool", "s", 0.01, mTao);
    addConstant("k_cs", "Steady state characteristic due to spring", "m^3/(s Pa)", 1e-8, mKcs);
    addConstant("k_cf", "Steady state characteristic due to flow forces", "m^3/(s Pa)", 1e-8, mKcf);
    addConstant("q_nom", "Flow with fully open valve and pressure drop p_nom", "m^3/s", 0.001, mQnom);
    addConstant("p_nom", "Nominal pressure drop", "Pa", 7e6, mPnom);
}

void HydraulicOverCenterValve::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPC_p = getSafeNodeDataPtr(mpPC, NodeHydraulic::Pressure);
    mpPC_c = getSafeNodeDataPtr(mpPC, NodeHydraulic::WaveVariable);

    mPrevX0 = 0.0;
    mCs = std::sqrt(mPnom) / mKcs;
    mCf = 1.0 / (mKcf * std::sqrt(mPnom));
    mX0max = mQnom / std::sqrt(mPnom);

    const double wc = 1.0 / mTao;
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 1.0 / wc};
    mFilter.initialize(mTimestep, num, den, 0.0, 0.0, 0.0, mX0max);
}

void HydraulicOverCenterValve::simulateOneTimestep()
{
    // Spool balance uses the node pressures of the previous step.
    double p1 = *mpP1_p, c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double p2 = *mpP2_p, c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    double pControl = *mpPC_p;
    const double cControl = *mpPC_c;
    const double pRef = *mpPref, ph = *mpPh, aRatio = *mpAratio;

    const double b1 = mCs + mCf * (p1 - p2);
    const double xs = (p1 - pRef + aRatio * pControl) / b1;
    const double xh = ph / b1;
    const double xsh = mHyst.getValue(xs, xh, mPrevX0);
    const double x0 = mFilter.update(xsh);

    mTurb.setFlowCoefficient(x0);
    double q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
    double q1 = -q2;
    p1 = c1 + Zc1 * q1;
    p2 = c2 + Zc2 * q2;

    pControl = std::max(0.0, cControl);

    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) {
        q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
        q1 = -q2;
        p1 = c1 + Zc1 * q1;
        p2 = c2 + Zc2 * q2;
        if (p1 < 0.0) { p1 = 0.0; }
        if (p2 < 0.0) { p2 = 0.0; }
    }

    mPrevX0 = x0;
    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpPC_p = pControl;
    *mpXv = x0;
}

TLMHUB_REGISTER_COMPONENT(HydraulicOverCenterValve, "Hydraulic")

} // namespace tlmhub
