#include "core/components/hydraulic/HydraulicCentrifugalPump.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

#include <cmath>

namespace tlmhub {

void HydraulicCentrifugalPump::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addInputVariable("omegap", "Pump speed", "rad/s", 157.0, &mp_omegap);
    addInputVariable("kl", "Flow loss coefficient", "-", 0.1, &mp_kl);
    addInputVariable("b", "Impeller outlet axial width", "m", 0.03, &mp_b);
    addInputVariable("d", "Impeller diameter", "m", 0.3, &mp_d);
    addInputVariable("beta2", "Outlet blade angle", "rad", 1.57, &mp_beta2);
    addInputVariable("Ap", "Outlet flow area", "m^2", 0.001, &mp_Ap);
    addInputVariable("rho", "Fluid density", "kg/m2", 870.0, &mp_rho);
    addInputVariable("Kcp", "Leakage coefficient", "m^3/s/Pa", 1.0e-11, &mp_Kcp);
    addInputVariable("Bp", "Viscous friction coefficient", "Nm/(rad/s)", 0.1, &mp_Bp);
    addOutputVariable("q2e", "Flow (not computed)", "m^3/s", 0.0, &mp_q2e);
    addOutputVariable("torp", "Shaft torque", "Nm", 0.0, &mp_torp);
    addOutputVariable("Pin", "Input power", "W", 0.0, &mp_Pin);
    addOutputVariable("Pout", "Output power", "W", 0.0, &mp_Pout);
}

void HydraulicCentrifugalPump::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    p1 = *mpP1_p; q1 = *mpP1_q; c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    p2 = *mpP2_p; q2 = *mpP2_q; c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    q2e = *mp_q2e; torp = *mp_torp; Pin = *mp_Pin; Pout = *mp_Pout;
}

void HydraulicCentrifugalPump::simulateOneTimestep()
{
    c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    const double omegap = *mp_omegap, kl = *mp_kl, b = *mp_b, d = *mp_d, beta2 = *mp_beta2;
    const double Ap = *mp_Ap, rho = *mp_rho, Kcp = *mp_Kcp, Bp = *mp_Bp;

    mX[0] = q2; mX[1] = torp; mX[2] = p1; mX[3] = p2;
    for (int iter = 1; iter <= 2; ++iter) {
        // L switches the flow off when sucking from an empty inlet.
        const double L = limit(onNegative(q2) + onPositive(p1), 0.0, 1.0);
        const double X = 2.0 * (p1 - p2 + omegap * rho * (0.25 * b * (d * d) * omegap - 0.159155 * q2 * rho * Cot(beta2)) / b) / (kl * rho);
        const double S = signedSquareL(X, 10.0);
        const double dS = dxSignedSquareL(X, 10.0);
        const double A2 = Ap * Ap;
        const double Dn = A2 * (-0.001 - omegap);

        mF[0] = q2 - L * (Kcp * (p1 - p2) + Ap * S);
        mF[1] = (A2 * (Bp * omegap * (0.001 + omegap) + Kcp * (p1 * p1) - 2.0 * Kcp * p1 * p2 + Kcp * (p2 * p2) - p1 * q2 + p2 * q2)
                 + kl * (-0.5 * Kcp * p1 + 0.5 * Kcp * p2 + 0.5 * q2) * (q2 * q2) * rho) / Dn + torp;
        mF[2] = p1 - lowLimit(c1 - q2 * Zc1, 0.0);
        mF[3] = p2 - lowLimit(c2 + q2 * Zc2, 0.0);

        mJ[0][0] = 1.0 + 0.31831 * Ap * omegap * rho * Cot(beta2) * dS * L / (b * kl);
        mJ[0][1] = 0.0;
        mJ[0][2] = -(Kcp + 2.0 * Ap * dS / (kl * rho)) * L;
        mJ[0][3] = -(-Kcp - 2.0 * Ap * dS / (kl * rho)) * L;
        mJ[1][0] = (A2 * (-p1 + p2) + 2.0 * kl * (-0.5 * Kcp * p1 + 0.5 * Kcp * p2 + 0.5 * q2) * q2 * rho + 0.5 * kl * (q2 * q2) * rho) / Dn;
        mJ[1][1] = 1.0;
        mJ[1][2] = (A2 * (2.0 * Kcp * p1 - 2.0 * Kcp * p2 - q2) - 0.5 * Kcp * kl * (q2 * q2) * rho) / Dn;
        mJ[1][3] = (A2 * (-2.0 * Kcp * p1 + 2.0 * Kcp * p2 + q2) + 0.5 * Kcp * kl * (q2 * q2) * rho) / Dn;
        mJ[2][0] = Zc1 * dxLowLimit(c1 - q2 * Zc1, 0.0);
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[3][0] = -Zc2 * dxLowLimit(c2 + q2 * Zc2, 0.0);
        mJ[3][1] = 0.0;
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicCentrifugalPump: singular Jacobian");
        }
        q2 = mX[0]; torp = mX[1]; p1 = mX[2]; p2 = mX[3];
        q1 = -q2;
        Pin = omegap * torp;
        Pout = (p2 - p1) * q2;
    }

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mp_q2e = q2e;
    *mp_torp = torp;
    *mp_Pin = Pin;
    *mp_Pout = Pout;
}

TLMHUB_REGISTER_COMPONENT(HydraulicCentrifugalPump, "Hydraulic")

} // namespace tlmhub
