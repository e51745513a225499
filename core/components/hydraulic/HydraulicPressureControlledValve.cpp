#include "core/components/hydraulic/HydraulicPressureControlledValve.h"

#include "core/ComponentFactory.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicPressureControlledValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPOpen = addPowerPort("P_OPEN", NodeType::Hydraulic);
    mpPClose = addPowerPort("P_CLOSE", NodeType::Hydraulic);

    addInputVariable("p_ref", "Reference Opening Pressure", "Pa", 2e6, &mpPref);
    addInputVariable("p_h", "Hysteresis Width", "Pa", 5e5, &mpPh);
    addOutputVariable("x0", "Equivalent spool position", "", 0.0, &mpX0);

    addConstant("tao", "Time Constant of Spool", "s", 0.01, mTao);
    addConstant("k_cs", "Steady State Characteristic due to Spring", "m^3/(s Pa)", 1e-8, mKcs);
    addConstant("k_cf", "Steady State Characteristic due to Flow Forces", "m^3/(s Pa)", 1e-8, mKcf);
    addConstant("q_nom", "Flow with Fully Open Valve and pressure drop p_nom", "m^3/s", 0.001, mQnom);
    addConstant("p_nom", "Nominal pressure drop", "Pa", 7e6, mPnom);
}

void HydraulicPressureControlledValve::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPOpen_p = getSafeNodeDataPtr(mpPOpen, NodeHydraulic::Pressure);
    mpPOpen_c = getSafeNodeDataPtr(mpPOpen, NodeHydraulic::WaveVariable);
    mpPClose_p = getSafeNodeDataPtr(mpPClose, NodeHydraulic::Pressure);
    mpPClose_c = getSafeNodeDataPtr(mpPClose, NodeHydraulic::WaveVariable);

    mPrevX0 = 0.0;
    mCs = std::sqrt(mPnom) / mKcs;
    mCf = 1.0 / (mKcf * std::sqrt(mPnom));
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, mTao};
    mFilter.initialize(mTimestep, num, den, 0.0, 0.0, 0.0, mQnom / std::sqrt(mPnom));
}

void HydraulicPressureControlledValve::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;

    // Spool balance on the previous step's pressures. Unlike the relief valve the
    // flow-force term is not cut off for p1 < p2, and the lag has a fixed break frequency.
    const double b1 = mCs + mCf * (*mpP1_p - *mpP2_p);
    const double xs = (*mpPOpen_p - *mpPref - *mpPClose_p) / b1;
    const double xsh = mHyst.getValue(xs, *mpPh / b1, mPrevX0);
    const double x0 = mFilter.update(xsh);

    mTurb.setFlowCoefficient(x0);
    double q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
    double q1 = -q2;
    double p1 = c1 + Zc1 * q1;
    double p2 = c2 + Zc2 * q2;

    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) {
        q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
        q1 = -q2;
        p1 = std::max(c1 + Zc1 * q1, 0.0);
        p2 = std::max(c2 + Zc2 * q2, 0.0);
    }

    mPrevX0 = x0;
    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    // Pilot ports: no flow, so the pressure is the wave variable (not below 0).
    *mpPOpen_p = std::max(*mpPOpen_c, 0.0);
    *mpPClose_p = std::max(*mpPClose_c, 0.0);
    *mpX0 = x0;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlledValve, "Hydraulic")

} // namespace tlmhub
