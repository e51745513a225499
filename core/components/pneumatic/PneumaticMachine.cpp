#include "core/components/pneumatic/PneumaticMachine.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

namespace {
// Truncated 1/(2 pi) and 1/pi as generated for the mechanical equations, and the
// full-precision 1/(2 pi) of the flow equation; the mix is part of the reference.
constexpr double k1 = 0.159155;
constexpr double k2 = 0.31831;
constexpr double kq = 0.15915494309189535;
// Length of the delay line of the generated original (only d12 is read two steps back).
constexpr int kDelaySteps = 9;
} // namespace

void PneumaticMachine::configure()
{
    mpPp1 = addPowerPort("Pp1", NodeType::Pneumatic);
    mpPp2 = addPowerPort("Pp2", NodeType::Pneumatic);
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    addInputVariable("Dm", "Displacement", "m3", 0.000049999999999999996, &mpDm);
    addInputVariable("Cim", "Leak coeff.", "m3/(s Pa)", 0.0, &mpCim);
    addInputVariable("Bm", "Visc. friction coeff.", "N/m/s", 0.0, &mpBm);
    addInputVariable("Jm", "Moment of inertia", "kg/m2", 0.1, &mpJm);
    addInputVariable("R", "Gas constant", "J/Kg K", 287.0, &mpR);
    addInputVariable("cv", "heatcoeff", "J/Kg K", 718.0, &mpCv);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Dm", "Cim", "Bm", "Jm", "R", "cv"}, false);
}

void PneumaticMachine::computeDelayedParts(double& d11, double& d12, double& d21) const
{
    const double dt = mTimestep, dt2 = dt * dt;
    const double Dm = mDm, Bm = mBm, Jm = mJm;
    d11 = (-k2 * Dm * dt2 * mP1 + k2 * Dm * dt2 * mP2 - 8.0 * Jm * mTheta + 2.0 * dt2 * mTorque)
          / (4.0 * Jm + 2.0 * Bm * dt);
    d12 = (-k1 * Dm * dt2 * mP1 + k1 * Dm * dt2 * mP2 + 4.0 * Jm * mTheta - 2.0 * Bm * dt * mTheta + dt2 * mTorque)
          / (4.0 * Jm + 2.0 * Bm * dt);
    d21 = (-k1 * Dm * dt * mP1 + k1 * Dm * dt * mP2 + dt * mTorque - 2.0 * Jm * mW + Bm * dt * mW)
          / (2.0 * Jm + Bm * dt);
}

void PneumaticMachine::initialize()
{
    mPp1.bind(mpPp1);
    mPp2.bind(mpPp2);
    mpPmr1_t = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpPmr1_a = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr1_J = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::EquivalentInertia);

    // Start values form the first Newton guess.
    mP1 = *mPp1.p;
    mDE1 = *mPp1.dE;
    mP2 = *mPp2.p;
    mQm2 = *mPp2.qm;
    mDE2 = *mPp2.dE;
    mTorque = *mpPmr1_t;
    mTheta = *mpPmr1_a;
    mW = *mpPmr1_w;
    mEqInertia = *mpPmr1_J;

    // Hopsan quirk: all inputs are sampled only here.
    mDm = *mpDm;
    mCim = *mpCim;
    mBm = *mpBm;
    mJm = *mpJm;
    mR = *mpR;
    mCv = *mpCv;

    double d11 = 0.0, d12 = 0.0, d21 = 0.0;
    computeDelayedParts(d11, d12, d21);
    mD11 = d11;
    mD21 = d21;
    mD12Buffer.initialize(kDelaySteps, d12);
    mD12Used = mD12Buffer.getIdx(1);
}

void PneumaticMachine::simulateOneTimestep()
{
    const double T1 = *mPp1.T, c1 = *mPp1.c, Zc1 = *mPp1.Zc;
    const double T2 = *mPp2.T, c2 = *mPp2.c, Zc2 = *mPp2.Zc;
    const double cm = *mpPmr1_c, Zcm = *mpPmr1_Zc;
    const double dt = mTimestep, dt2 = dt * dt;
    const double Dm = mDm, Cim = mCim, Bm = mBm, Jm = mJm, R = mR;
    const double cp = mCv + R;
    const double den4 = 4.0 * Jm + 2.0 * Bm * dt;
    const double den2 = 2.0 * Jm + Bm * dt;
    const double flowDen = R * (1.0 + T1) * T2;

    mX[0] = mTheta;
    mX[1] = mW;
    mX[2] = mQm2;
    mX[3] = mDE1;
    mX[4] = mDE2;
    mX[5] = mP1;
    mX[6] = mP2;
    mX[7] = mTorque;

    for (int iter = 1; iter <= 2; ++iter) {
        const double theta = mX[0], w = mX[1], qm2 = mX[2], dE1 = mX[3], dE2 = mX[4], p1 = mX[5], p2 = mX[6],
                     T = mX[7];
        const double neg = onNegative(qm2), pos = onPositive(qm2);
        const double negM = onNegative(-qm2), posM = onPositive(-qm2);
        // Leakage/displacement flow with the generated (1 + T1) factors kept literally.
        const double leakNeg = Cim * (p1 * (-1.0 - 1.0 * T1) + p2 * (1.0 + T1)) + Dm * (-kq - kq * T1) * w;
        const double leakPos = Cim * (-1.0 * p1 + p2) - kq * Dm * w;

        mF[0] = theta + (dt2 * (-k1 * Dm * p1 + k1 * Dm * p2 + T)) / den4 + mD11 + mD12Used;
        mF[1] = (dt * (-k1 * Dm * p1 + k1 * Dm * p2 + T)) / den2 + w + mD21;
        mF[2] = qm2 + (p2 * leakNeg * neg + p1 * T2 * leakPos * pos) / flowDen;
        mF[3] = dE1 + cp * qm2 * T1 * negM + (cp * qm2 * T2 + T * w) * posM;
        mF[4] = dE2 - cp * qm2 * T2 * neg + (-(cp * qm2 * T1) + T * w) * pos;
        mF[5] = p1 - lowLimit(c1 + dE1 * Zc1, 0.0);
        mF[6] = p2 - lowLimit(c2 + dE2 * Zc2, 0.0);
        mF[7] = -cm + T - w * Zcm;

        for (int r = 0; r < 8; ++r) {
            for (int c = 0; c < 8; ++c) { mJ[r][c] = 0.0; }
        }
        mJ[0][0] = 1.0;
        mJ[0][5] = (-k1 * Dm * dt2) / den4;
        mJ[0][6] = (k1 * Dm * dt2) / den4;
        mJ[0][7] = dt2 / den4;
        mJ[1][1] = 1.0;
        mJ[1][5] = (-k1 * Dm * dt) / den2;
        mJ[1][6] = (k1 * Dm * dt) / den2;
        mJ[1][7] = dt / den2;
        mJ[2][1] = (p2 * (Dm * (-kq - kq * T1)) * neg + (-kq * Dm) * p1 * T2 * pos) / flowDen;
        mJ[2][2] = 1.0;
        mJ[2][5] = (p2 * (Cim * (-1.0 - 1.0 * T1)) * neg - 1.0 * Cim * p1 * T2 * pos + T2 * leakPos * pos) / flowDen;
        mJ[2][6] = (p2 * (Cim * (1.0 + T1)) * neg + leakNeg * neg + 1.0 * Cim * p1 * T2 * pos) / flowDen;
        mJ[3][1] = T * posM;
        mJ[3][2] = cp * T1 * negM + cp * T2 * posM;
        mJ[3][3] = 1.0;
        mJ[3][7] = w * posM;
        mJ[4][1] = T * pos;
        mJ[4][2] = -(cp * T2 * neg) - cp * T1 * pos;
        mJ[4][4] = 1.0;
        mJ[4][7] = w * pos;
        mJ[5][3] = -(Zc1 * dxLowLimit(c1 + dE1 * Zc1, 0.0));
        mJ[5][5] = 1.0;
        mJ[6][4] = -(Zc2 * dxLowLimit(c2 + dE2 * Zc2, 0.0));
        mJ[6][6] = 1.0;
        mJ[7][1] = -Zcm;
        mJ[7][7] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("PneumaticMachine: singular Jacobian in Newton iteration");
            return;
        }
    }

    mTheta = mX[0];
    mW = mX[1];
    mQm2 = mX[2];
    mDE1 = mX[3];
    mDE2 = mX[4];
    mP1 = mX[5];
    mP2 = mX[6];
    mTorque = mX[7];

    double d11 = 0.0, d12 = 0.0, d21 = 0.0;
    computeDelayedParts(d11, d12, d21);
    mD11 = d11;
    mD21 = d21;
    // d12 reaches the residual two steps after it was computed.
    mD12Used = mD12Buffer.getIdx(0);
    mD12Buffer.update(d12);

    *mPp1.p = mP1;
    *mPp1.qm = -mQm2;
    *mPp1.dE = mDE1;
    *mPp2.p = mP2;
    *mPp2.qm = mQm2;
    *mPp2.dE = mDE2;
    *mpPmr1_t = mTorque;
    *mpPmr1_a = mTheta;
    *mpPmr1_w = mW;
    *mpPmr1_J = mEqInertia;
}

TLMHUB_REGISTER_COMPONENT(PneumaticMachine, "Pneumatic")

} // namespace tlmhub
