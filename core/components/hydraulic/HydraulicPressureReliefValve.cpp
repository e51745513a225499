#include "core/components/hydraulic/HydraulicPressureReliefValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicPressureReliefValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addOutputVariable("xv", "Equivalent spool position", "", &mpXv);
    addInputVariable("p_max", "Maximum opening pressure", "Pa", 2e7, &mpPmax);
    addInputVariable("tao", "Time constant of spool", "s", 0.01, &mpTao);
    addInputVariable("p_h", "Hysteresis width", "Pa", 5e5, &mpPh);

    addConstant("k_cs", "Steady state characteristic due to spring", "m^3/(s Pa)", 1e-8, mKcs);
    addConstant("k_cf", "Steady state characteristic due to flow forces", "m^3/(s Pa)", 1e-8, mKcf);
    addConstant("q_nom", "Flow with fully open valve and pressure drop p_nom", "m^3/s", 0.001, mQnom);
}

void HydraulicPressureReliefValve::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    mX0max = mQnom / std::sqrt(mPnom);
    mCs = std::sqrt(mPnom) / mKcs;
    mCf = 1.0 / (mKcf * std::sqrt(mPnom));
    mPrevX0 = 0.0;

    const double wc = 1.0 / (*mpTao);
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 1.0 / wc};
    mFilter.initialize(mTimestep, num, den, 0.0, 0.0, 0.0, mX0max);
}

void HydraulicPressureReliefValve::simulateOneTimestep()
{
    // Node pressures are those of the previous step (used for the spool force balance).
    double p1 = *mpP1_p, c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double p2 = *mpP2_p, c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double pmax = *mpPmax, ph = *mpPh, tao = *mpTao;

    double b1 = mCs + (p1 - p2) * mCf;
    if ((p1 - p2) * mCf < 0.0) { b1 = mCs; }

    double s;
    if (p1 > p2) { s = std::sqrt(p1 - p2); }
    else { s = std::sqrt(p2 - p1); }
    double gamma;
    if (2.0 * s + (Zc1 + Zc2) * mPrevX0 != 0.0) {
        gamma = 2.0 * s / (2.0 * s + (Zc1 + Zc2) * mPrevX0);
    } else {
        gamma = 1.0;
    }
    double b2 = gamma * (Zc1 + Zc2) * s;
    if (b2 < 0.0) { b2 = 0.0; }

    const double xs = (gamma * c1 + b2 * mPrevX0 / 2.0 - pmax) / (b1 + b2);
    const double xh = ph / (b1 + b2);
    const double xsh = mHyst.getValue(xs, xh, mPrevX0);

    // Break frequency follows the load; the filter keeps its delayed values.
    const double wc = (1.0 + b2 / b1) * 1.0 / tao;
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 1.0 / wc};
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
        x0 = mFilter.value();
        mTurb.setFlowCoefficient(x0);
        q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
        q1 = -q2;
        p2 = c2 + Zc2 * q2;
        p1 = c1 + Zc1 * q1;
        if (p1 < 0.0) { p1 = 0.0; }
        if (p2 < 0.0) { p2 = 0.0; }
    }

    mPrevX0 = x0;
    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpXv = x0;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureReliefValve, "Hydraulic")

} // namespace tlmhub
