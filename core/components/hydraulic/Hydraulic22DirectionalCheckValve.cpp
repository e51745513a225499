#include "core/components/hydraulic/Hydraulic22DirectionalCheckValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>

namespace tlmhub {

void Hydraulic22DirectionalCheckValve::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
    addInputVariable("in", "Open (> 0.5) or checked", "-", 0.0, &mpIn);
    addInputVariable("Kv_open", "Flow coefficient in open position", "(m^3/s)/sqrt(Pa)", 5e-7, &mpKvOpen);
    addInputVariable("Kv_check", "Flow coefficient in checked position", "(m^3/s)/sqrt(Pa)", 5e-7, &mpKvCheck);
    addInputVariable("F_s", "Cracking pressure of the check function", "Pa", 0.0, &mpFs);
    addOutputVariable("out", "Filtered switch position", "-", 0.0, &mpOut);
}

void Hydraulic22DirectionalCheckValve::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    const double y0 = limit(*mpOut, 0.0, 1.0);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, 0.0, 1.0);

    // The reference runs one step already at initialisation.
    simulateOneTimestep();
}

void Hydraulic22DirectionalCheckValve::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double kvOpen = *mpKvOpen, kvCheck = *mpKvCheck, Fs = *mpFs;

    if (doubleToBool(*mpIn)) { mSpool.update(1.0); }
    else { mSpool.update(0.0); }
    const double out = mSpool.value();
    const double outnom = std::max(out, 0.0);

    double q1, q2, p1, p2;
    auto solve = [&]() {
        if (outnom > 0.5) {
            mTurb.setFlowCoefficient(kvOpen);
            q2 = mTurb.getFlow(c1, c2, Zc1, Zc2);
        } else {
            // Check function compares wave variables, not pressures.
            mTurb.setFlowCoefficient(kvCheck);
            if (c1 > c2 + Fs) { q2 = mTurb.getFlow(c1, c2, Zc1, Zc2); }
            else { q2 = 0.0; }
        }
        q1 = -q2;
        p1 = c1 + q1 * Zc1;
        p2 = c2 + q2 * Zc2;
    };
    solve();

    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) { solve(); }

    *mpP1_q = q1;
    *mpP1_p = p1;
    *mpP2_q = q2;
    *mpP2_p = p2;
    *mpOut = outnom;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic22DirectionalCheckValve, "Hydraulic")

} // namespace tlmhub
