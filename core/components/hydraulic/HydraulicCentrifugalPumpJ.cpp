#include "core/components/hydraulic/HydraulicCentrifugalPumpJ.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

#include <cmath>

namespace tlmhub {

void HydraulicCentrifugalPumpJ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);

    addInputVariable("kl", "Flow loss coefficient", "-", 0.1, &mp_kl);
    addInputVariable("b", "Impeller outlet axial width", "m", 0.03, &mp_b);
    addInputVariable("d", "Impeller diameter", "m", 0.3, &mp_d);
    addInputVariable("beta2", "Outlet blade angle", "rad", 1.57, &mp_beta2);
    addInputVariable("Ap", "Outlet flow area", "m^2", 0.001, &mp_Ap);
    addInputVariable("rho", "Fluid density", "kg/m^3", 870.0, &mp_rho);
    addInputVariable("Kcp", "Leakage coefficient", "m^3/s/Pa", 1.0e-11, &mp_Kcp);
    addInputVariable("Bp", "Viscous friction coefficient", "Nm/(rad/s)", 0.1, &mp_Bp);
    addInputVariable("Jp", "Shaft inertia", "N/m/s", 0.1, &mp_Jp);
    addOutputVariable("q2e", "Uncorrected flow", "m^3/s", 0.0, &mp_q2e);
    addOutputVariable("Pin", "Input power", "W", 0.0, &mp_Pin);
    addOutputVariable("Pout", "Output power", "W", 0.0, &mp_Pout);
}

double HydraulicCentrifugalPumpJ::delayedPart() const
{
    const double h = mTimestep;
    const double A2 = Ap * Ap;
    const double aw = std::fabs(wmr1);
    return (A2 * Kcp * h * (p1 * p1) - 2.0 * A2 * Kcp * h * p1 * p2 + A2 * Kcp * h * (p2 * p2) - A2 * h * p1 * q2e
            + A2 * h * p2 * q2e - 0.5 * Kcp * kl * h * p1 * (q2 * q2) * rho + 0.5 * Kcp * kl * h * p2 * (q2 * q2) * rho
            + 0.5 * kl * h * (q2 * q2) * q2e * rho - 0.001 * A2 * h * tormr1 + 0.002 * A2 * Jp * wmr1
            - 0.001 * A2 * Bp * h * wmr1 - A2 * h * tormr1 * aw + 2.0 * A2 * Jp * wmr1 * aw - A2 * Bp * h * wmr1 * aw)
           / (-0.002 * A2 * Jp - 0.001 * A2 * Bp * h - 2.0 * A2 * Jp * aw - A2 * Bp * h * aw);
}

void HydraulicCentrifugalPumpJ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPmr1_t = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpPmr1_a = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr1_Je = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::EquivalentInertia);

    p1 = *mpP1_p; q1 = *mpP1_q; c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    p2 = *mpP2_p; q2 = *mpP2_q; c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    tormr1 = *mpPmr1_t; thetamr1 = *mpPmr1_a; wmr1 = *mpPmr1_w;
    cmr1 = *mpPmr1_c; Zcmr1 = *mpPmr1_Zc; eqInertiamr1 = *mpPmr1_Je;
    kl = *mp_kl; b = *mp_b; d = *mp_d; beta2 = *mp_beta2; Ap = *mp_Ap;
    rho = *mp_rho; Kcp = *mp_Kcp; Bp = *mp_Bp; Jp = *mp_Jp;
    q2e = *mp_q2e; Pin = *mp_Pin; Pout = *mp_Pout;

    mDprev = delayedPart();
}

void HydraulicCentrifugalPumpJ::simulateOneTimestep()
{
    const double h = mTimestep;
    c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    cmr1 = *mpPmr1_c; Zcmr1 = *mpPmr1_Zc;
    kl = *mp_kl; b = *mp_b; d = *mp_d; beta2 = *mp_beta2; Ap = *mp_Ap;
    rho = *mp_rho; Kcp = *mp_Kcp; Bp = *mp_Bp; Jp = *mp_Jp;

    mX[0] = q2e; mX[1] = wmr1; mX[2] = p1; mX[3] = p2; mX[4] = tormr1;
    for (int iter = 1; iter <= 2; ++iter) {
        // q2 (corrected flow) is not an unknown: it holds the last computed value.
        const double L = limit(onNegative(q2) + onPositive(p1), 0.0, 1.0);
        const double X = 2.0 * (p1 - p2 + rho * wmr1 * (0.25 * b * (d * d) * wmr1 + 0.159155 * q2e * rho * Cot(beta2)) / b) / (kl * rho);
        const double S = signedSquareL(X, 10.0);
        const double dS = dxSignedSquareL(X, 10.0);
        const double A2 = Ap * Ap;
        const double aw = std::fabs(wmr1);
        const double dA = dxAbs(wmr1);
        const double den0 = -0.002 * Jp - 0.001 * Bp * h - 2.0 * Jp * aw - Bp * h * aw;
        const double Den = A2 * den0;
        const double Num = h * (kl * (q2 * q2) * (-0.5 * Kcp * p1 + 0.5 * Kcp * p2 + 0.5 * q2e) * rho
                                + A2 * (Kcp * (p1 * p1) - 2.0 * Kcp * p1 * p2 + Kcp * (p2 * p2) - p1 * q2e + p2 * q2e - 0.001 * tormr1)
                                - A2 * tormr1 * aw);

        mF[0] = q2e - L * (Kcp * (p1 - p2) + Ap * S);
        mF[1] = wmr1 + Num / Den + mDprev;
        mF[2] = p1 - lowLimit(c1 - q2 * Zc1, 0.0);
        mF[3] = p2 - lowLimit(c2 + q2 * Zc2, 0.0);
        mF[4] = -cmr1 + tormr1 - wmr1 * Zcmr1;

        mJ[0][0] = 1.0 - 0.31831 * Ap * rho * wmr1 * Cot(beta2) * dS * L / (b * kl);
        mJ[0][1] = -2.0 * Ap * (0.25 * (d * d) * rho * wmr1 + rho * (0.25 * b * (d * d) * wmr1 + 0.159155 * q2e * rho * Cot(beta2)) / b) * dS * L / (kl * rho);
        mJ[0][2] = -(Kcp + 2.0 * Ap * dS / (kl * rho)) * L;
        mJ[0][3] = -(-Kcp - 2.0 * Ap * dS / (kl * rho)) * L;
        mJ[0][4] = 0.0;
        mJ[1][0] = h * (A2 * (-p1 + p2) + 0.5 * kl * (q2 * q2) * rho) / Den;
        mJ[1][1] = 1.0 - Num * (-2.0 * Jp * dA - Bp * h * dA) / (A2 * (den0 * den0)) + h * (-A2 * tormr1 * dA) / Den;
        mJ[1][2] = h * (A2 * (2.0 * Kcp * p1 - 2.0 * Kcp * p2 - q2e) - 0.5 * Kcp * kl * (q2 * q2) * rho) / Den;
        mJ[1][3] = h * (A2 * (-2.0 * Kcp * p1 + 2.0 * Kcp * p2 + q2e) + 0.5 * Kcp * kl * (q2 * q2) * rho) / Den;
        mJ[1][4] = h * (-0.001 * A2 - A2 * aw) / Den;
        for (int j = 0; j < 5; ++j) {
            mJ[2][j] = 0.0;
            mJ[3][j] = 0.0;
            mJ[4][j] = 0.0;
        }
        mJ[2][2] = 1.0;
        mJ[3][3] = 1.0;
        mJ[4][1] = -Zcmr1;
        mJ[4][4] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicCentrifugalPumpJ: singular Jacobian");
        }
        q2e = mX[0]; wmr1 = mX[1]; p1 = mX[2]; p2 = mX[3]; tormr1 = mX[4];
        q2 = q2e * onPositive(p1);
        q1 = -q2;
        Pin = -(tormr1 * wmr1);
        Pout = (p2 - p1) * q2;
    }

    mDprev = delayedPart();

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpPmr1_t = tormr1;
    *mpPmr1_a = thetamr1; // never integrated (reference quirk)
    *mpPmr1_w = wmr1;
    *mpPmr1_Je = eqInertiamr1;
    *mp_q2e = q2e;
    *mp_Pin = Pin;
    *mp_Pout = Pout;
}

TLMHUB_REGISTER_COMPONENT(HydraulicCentrifugalPumpJ, "Hydraulic")

} // namespace tlmhub
