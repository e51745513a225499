#include "core/components/hydraulic/HydraulicMachineC.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>

namespace tlmhub {

void HydraulicMachineC::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::MechanicRotational);

    addInputVariable("eps", "Displacement setting", "-", 1.0, &mpEps);
    addInputVariable("Beta_e", "Bulk modulus", "Pa", 1.0e9, &mpBetae);
    addInputVariable("V_1", "Volume at port 1", "m^3", 0.005, &mpV1);
    addInputVariable("V_2", "Volume at port 2", "m^3", 0.005, &mpV2);
    addInputVariable("D_m", "Displacement", "m^3/rev", 5.0e-5, &mpDm);
    addInputVariable("C_lm", "Leakage coefficient", "m^3/(s Pa)", 1.0e-12, &mpClm);
    addInputVariable("B_m", "Viscous friction coefficient", "Nms/rad", 0.0, &mpBm);
    addConstant("J_em", "Equivalent inertia (for the minimum volume)", "kg m^2", 1.0, mJem);

    setDefaultStartValue(mpP1, NodeHydraulic::Pressure, 1.0e5);
    setDefaultStartValue(mpP2, NodeHydraulic::Pressure, 1.0e5);
}

void HydraulicMachineC::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_t = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::Torque);
    mpP3_w = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::AngularVelocity);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::WaveVariable);
    mpP3_Zc = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::CharImpedance);

    const double h = mTimestep;
    const double p1 = *mpP1_p, q1 = *mpP1_q, p2 = *mpP2_p, q2 = *mpP2_q;
    const double t3 = *mpP3_t, w3 = *mpP3_w;
    const double eps = *mpEps; // not limited at initialisation
    const double betae = *mpBetae, V1 = *mpV1, V2 = *mpV2, Dm = *mpDm, Clm = *mpClm, Bm = *mpBm;

    const double dpr = Dm / (pi * 2.0);
    const double dpe = dpr * eps;
    const double ka = 1.0 / (1.0 - mAlfa);

    // Smallest volume that keeps the shaft coupling stable.
    mV1min = 2.0 * ka * betae * h * h * dpr * dpr / (2.0 * mWfak * mJem);
    mV2min = mV1min;
    double v1e = V1, v2e = V2;
    if (v1e < mV1min) { v1e = mV1min; }
    if (v2e < mV2min) { v2e = mV2min; }

    const double Zc1 = 2.0 * ka * betae * h / (2.0 * v1e);
    const double Zc2 = 2.0 * ka * betae * h / (2.0 * v2e);

    const double c1 = p1 - Zc1 * q1;
    const double c2 = p2 - Zc2 * q2;
    mDC1.initialize(1, c1);
    mDC2.initialize(1, c2);

    const double qp1 = dpe * w3;
    const double qp2 = -dpe * w3;
    mCp1 = p1 - Zc1 * (qp1 - Clm * (p1 - p2));
    mCp2 = p2 - Zc2 * (qp2 - Clm * (p2 - p1));
    mDCp1.initialize(1, mCp1);
    mDCp1e.initialize(1, mCp1);
    mDCp2.initialize(1, mCp2);
    mDCp2e.initialize(1, mCp2);

    const double c3 = t3;
    const double Zc3 = dpe * dpe * Zc1 + dpe * dpe * Zc2 + Bm;

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP1_c = c1;
    *mpP1_Zc = Zc1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP2_c = c2;
    *mpP2_Zc = Zc2;
    *mpP3_t = t3;
    *mpP3_c = c3;
    *mpP3_Zc = Zc3;
}

void HydraulicMachineC::simulateOneTimestep()
{
    const double h = mTimestep;
    const double p1 = *mpP1_p, q1 = *mpP1_q;
    double c1 = *mpP1_c;
    const double p2 = *mpP2_p, q2 = *mpP2_q;
    double c2 = *mpP2_c;
    const double w3 = *mpP3_w;
    double eps = *mpEps;
    const double betae = *mpBetae, V1 = *mpV1, V2 = *mpV2, Dm = *mpDm, Clm = *mpClm, Bm = *mpBm;
    const double alfa = mAlfa;

    const double v1e = std::max(V1, mV1min);
    const double v2e = std::max(V2, mV2min);
    const double dpr = Dm / (pi * 2.0);
    limitValue(eps, -1.0, 1.0);
    const double dpe = dpr * eps;
    const double ka = 1.0 / (1.0 - alfa);
    const double Zc1 = 2.0 * ka * betae * h / (2.0 * v1e);
    const double Zc2 = 2.0 * ka * betae * h / (2.0 * v2e);

    const double qp1 = dpe * w3;
    const double qp2 = -dpe * w3;

    // Pressures at the displacement side, including the internal leakage.
    const double pp1 = (mCp1 + qp1 * Zc1 + Clm * (mCp2 * Zc1 + mCp1 * Zc2)) / (Clm * (Zc1 + Zc2) + 1.0);
    const double pp2 = (mCp2 + qp2 * Zc2 + Clm * (mCp2 * Zc1 + mCp1 * Zc2)) / (Clm * (Zc1 + Zc2) + 1.0);

    const double pp1e = std::max(pp1, 0.0);
    const double pp2e = std::max(pp2, 0.0);
    const double qp1e = qp1 - Clm * (pp1e - pp2e);
    const double qp2e = qp2 - Clm * (pp2e - pp1e);

    const double pm1 = (0.0 + c1 + 2.0 * Zc1 * q1 + pp1 + Zc1 * qp1e) / 2.0;
    const double pm2 = (0.0 + c2 + 2.0 * Zc2 * q2 + pp2 + Zc2 * qp2e) / 2.0;

    // Filtered wave propagation (length-1 delays give a two-step lag, see reference).
    const double cp10 = 2.0 * pm1 - pp1 - Zc1 * qp1e;
    mCp1 = alfa * mDCp1.update(mCp1) + (1.0 - alfa) * cp10;
    const double c1e = 2.0 * pm1 - c1 - 2.0 * Zc1 * q1;
    c1 = alfa * mDC1.update(c1) + (1.0 - alfa) * c1e;
    const double cp20 = 2.0 * pm2 - pp2 - Zc2 * qp2e;
    mCp2 = alfa * mDCp2.update(mCp2) + (1.0 - alfa) * cp20;
    const double c2e = 2.0 * pm2 - c2 - 2.0 * Zc2 * q2;
    c2 = alfa * mDC2.update(c2) + (1.0 - alfa) * c2e;

    // Cavitation-limited version used for the shaft torque.
    const double p1e = std::max(p1, 0.0);
    const double pm1e = ((p1e + Zc1 * q1) + (pp1e + Zc1 * qp1e)) / 2.0;
    const double p2e = std::max(p2, 0.0);
    const double pm2e = ((p2e + Zc2 * q2) + (pp2e + Zc2 * qp2e)) / 2.0;
    const double cp10e = 2.0 * pm1e - pp1e - Zc1 * qp1e;
    const double cp20e = 2.0 * pm2e - pp2e - Zc2 * qp2e;
    const double cp1e = alfa * mDCp1e.getOldest() + (1.0 - alfa) * cp10e;
    const double cp2e = alfa * mDCp2e.getOldest() + (1.0 - alfa) * cp20e;
    mDCp1e.update(cp1e);
    mDCp2e.update(cp2e);

    const double c3 = (cp1e - cp2e) * dpe;
    const double Zc3 = dpe * dpe * (Zc1 + Zc2) + Bm;

    *mpP1_c = c1;
    *mpP1_Zc = Zc1;
    *mpP2_c = c2;
    *mpP2_Zc = Zc2;
    *mpP3_c = c3;
    *mpP3_Zc = Zc3;
}

TLMHUB_REGISTER_COMPONENT(HydraulicMachineC, "Hydraulic")

} // namespace tlmhub
