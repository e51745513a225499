#include "core/components/hydraulic/Hydraulic22DirectionalValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void Hydraulic22DirectionalValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addInputVariable("in", "Open (> 0.5) or closed", "-", 0.0, &mpIn);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f", "Fraction of spool circumference that is opening", "-", 1.0, &mpF);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);
    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
}

void Hydraulic22DirectionalValve::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    const double xvmax = *mpXvmax;
    const double y0 = limit(*mpXv, 0.0, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, 0.0, xvmax);

    simulateOneTimestep();
}

void Hydraulic22DirectionalValve::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double Cq = *mpCq, rho = *mpRho, d = *mpD, f = *mpF, xvmax = *mpXvmax;

    if (doubleToBool(*mpIn)) { mSpool.update(xvmax); }
    else { mSpool.update(0.0); }
    const double xv = mSpool.value();
    const double xnom = std::max(xv, 0.0);

    mTurb.setFlowCoefficient(Cq * f * pi * d * xnom * std::sqrt(2.0 / rho));
    double q = mTurb.getFlow(c1, c2, Zc1, Zc2);
    double q1 = -q, q2 = q;
    double p1 = c1 + q1 * Zc1, p2 = c2 + q2 * Zc2;

    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) {
        q = mTurb.getFlow(c1, c2, Zc1, Zc2);
        q1 = -q;
        q2 = q;
        p1 = c1 + q1 * Zc1;
        p2 = c2 + q2 * Zc2;
    }

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpXv = xnom;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic22DirectionalValve, "Hydraulic")

} // namespace tlmhub
