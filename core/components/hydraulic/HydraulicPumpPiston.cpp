#include "core/components/hydraulic/HydraulicPumpPiston.h"

#include "core/ComponentFactory.h"

#include <algorithm>

namespace tlmhub {

void HydraulicPumpPiston::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Mechanic);

    addInputVariable("A_1", "Piston area", "m^2", 0.001, &mpA1);
    addInputVariable("s_l", "Stroke", "m", 1.0, &mpSl);
    addInputVariable("V_1", "Dead volume in chamber", "m^3", 0.0003, &mpV1);
    addInputVariable("B_p", "Viscous friction coefficient of piston", "Ns/m", 1000.0, &mpBp);
    addInputVariable("Beta_e", "Bulk modulus", "Pa", 1.0e9, &mpBetae);
    addInputVariable("c_leak", "Leakage coefficient", "m^3/(s Pa)", 1.0e-11, &mpCleak);
    addInputVariable("F_0", "Spring force", "N", 1000.0, &mpF0);
}

void HydraulicPumpPiston::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP3_x = getSafeNodeDataPtr(mpP3, NodeMechanic::Position);
    mpP3_v = getSafeNodeDataPtr(mpP3, NodeMechanic::Velocity);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeMechanic::WaveVariable);
    mpP3_Zc = getSafeNodeDataPtr(mpP3, NodeMechanic::CharImpedance);
    mpP3_me = getSafeNodeDataPtr(mpP3, NodeMechanic::EquivalentMass);

    const double h = mTimestep;
    const double p1 = *mpP1_p;
    const double x3 = *mpP3_x, v3 = *mpP3_v;
    const double A1 = *mpA1, V_1 = *mpV1, Bp = *mpBp, betae = *mpBetae;
    const double cLeak = *mpCleak, F0 = *mpF0;

    // No half-stroke offset here (unlike the step), as in the reference.
    double V1 = V_1 + A1 * (-x3);
    const double V1min = betae * h * h * A1 * A1 / (mWfak * 1.0);
    if (V1 < V1min) { V1 = V1min; }

    const double Zc1 = 3.0 / 2.0 * betae / V1 * h / (1.0 - mAlpha);
    const double Zc3 = A1 * A1 * Zc1 + Bp;

    const double qi1 = v3 * A1;
    mCi1 = p1 + Zc1 * qi1;
    const double qLeak = cLeak * p1;
    mCl1 = p1 + Zc1 * (-qLeak);
    const double c3 = A1 * mCi1 + F0;

    *mpP1_c = p1 + Zc1 * (*mpP1_q);
    *mpP1_Zc = Zc1;
    *mpP3_c = c3;
    *mpP3_Zc = Zc3;
}

void HydraulicPumpPiston::simulateOneTimestep()
{
    const double h = mTimestep;
    const double q1 = *mpP1_q, c1 = *mpP1_c;
    double Zc1 = *mpP1_Zc; // previous step's impedance, used for the leakage flow
    const double x3 = *mpP3_x, v3 = *mpP3_v, me = *mpP3_me;
    const double A1 = *mpA1, sl = *mpSl, V_1 = *mpV1, Bp = *mpBp, betae = *mpBetae;
    const double cLeak = *mpCleak, F0 = *mpF0;
    const double alpha = mAlpha;

    const double qLeak = cLeak * mCl1 / (1.0 + cLeak * Zc1);
    const double qi1 = v3 * A1;

    double V1 = V_1 + A1 * (sl / 2.0 - x3);
    const double V1min = betae * h * h * A1 * A1 / (mWfak * me);
    if (V1 < V1min) { V1 = V1min; }

    Zc1 = 3.0 / 2.0 * betae / V1 * h / (1.0 - alpha);

    // Mean pressure of the three-port volume.
    const double p1mean =
        ((mCi1 + Zc1 * 2.0 * qi1) + (mCl1 + Zc1 * 2.0 * (-qLeak)) + (c1 + 2.0 * Zc1 * q1)) / 3.0;

    mCi1 = std::max(0.0, alpha * mCi1 + (1.0 - alpha) * (2.0 * p1mean - mCi1 - 2.0 * Zc1 * qi1));
    mCl1 = std::max(0.0, alpha * mCl1 + (1.0 - alpha) * (2.0 * p1mean - mCl1 - 2.0 * Zc1 * (-qLeak)));

    const double c3 = A1 * mCi1 + F0;
    const double Zc3 = A1 * A1 * Zc1 + Bp;

    *mpP1_c = alpha * c1 + (1.0 - alpha) * (2.0 * p1mean - c1 - 2.0 * Zc1 * q1);
    *mpP1_Zc = Zc1;
    *mpP3_c = c3;
    *mpP3_Zc = Zc3;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPumpPiston, "Hydraulic")

} // namespace tlmhub
