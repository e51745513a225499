#include "core/components/pneumatic/PneumaticOrifice.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void PneumaticOrifice::configure()
{
    mpPp1 = addPowerPort("Pp1", NodeType::Pneumatic);
    mpPp2 = addPowerPort("Pp2", NodeType::Pneumatic);
    addInputVariable("A0", "Area", "m2", 1.0e-6, &mpA0);
    addInputVariable("Cd", "Discharge coefficient", "", 0.65, &mpCd);
    addInputVariable("R", "Gas constant", "J/Kg K", 287.0, &mpR);
    addInputVariable("cv", "heatcoeff", "J/Kg K", 718.0, &mpCv);
    addInputVariable("eps", "Linearisation coeff", "", 0.02, &mpEps);
    addOutputVariable("qma", "Internal variable", "kg/s", 0.0, &mpQma);
    addOutputVariable("qmb", "Internal variable", "kg/s", 0.0, &mpQmb);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Cd", "R", "cv", "eps"}, false);
}

void PneumaticOrifice::initialize()
{
    mPp1.bind(mpPp1);
    mPp2.bind(mpPp2);

    // Start values form the first Newton guess.
    mP1 = *mPp1.p;
    mDE1 = *mPp1.dE;
    mP2 = *mPp2.p;
    mQm2 = *mPp2.qm;
    mDE2 = *mPp2.dE;
    mQma = *mpQma;
    mQmb = *mpQmb;

    // Hopsan quirk: only A0 is re-read every step.
    mCd = *mpCd;
    mR = *mpR;
    mCv = *mpCv;
    mEps = *mpEps;
    // Nothing is written to the nodes here.
}

void PneumaticOrifice::simulateOneTimestep()
{
    const double T1 = *mPp1.T, c1 = *mPp1.c, Zc1 = *mPp1.Zc;
    const double T2 = *mPp2.T, c2 = *mPp2.c, Zc2 = *mPp2.Zc;
    const double A0 = *mpA0;
    const double Cd = mCd, R = mR, cv = mCv, eps = mEps;

    // Gas constants (recomputed every step like the generated original).
    const double kappa = 1.0 + R / cv;
    const double e1 = (1.0 + kappa) / (-1.0 + kappa);
    const double Kg = std::sqrt((std::pow(2.0, e1) * kappa * std::pow(1.0 / (1.0 + kappa), e1)) / R);
    const double Ndenom = std::pow(2.0, -1.0 + e1) * (-1.0 + kappa) * std::pow(1.0 / (1.0 + kappa), e1);
    const double ek = kappa / (-1.0 + kappa);
    const double crit = std::pow(2.0, ek) * std::pow(1.0 / (1.0 + kappa), ek);
    const double cp = cv + R;
    const double ex1 = 1.0 + 1.0 / kappa; // exponent of the r^(1+1/kappa) term
    const double ex2 = 2.0 / kappa;       // exponent of the r^(2/kappa) term

    mX[0] = mQma;
    mX[1] = mQmb;
    mX[2] = mQm2;
    mX[3] = mDE1;
    mX[4] = mDE2;
    mX[5] = mP1;
    mX[6] = mP2;

    for (int iter = 1; iter <= 2; ++iter) {
        const double qma = mX[0], qmb = mX[1], qm2 = mX[2], dE1 = mX[3], dE2 = mX[4], p1 = mX[5], p2 = mX[6];

        const double r12 = p1 / p2; // ratio used when the flow goes 2 -> 1
        const double r21 = p2 / p1; // ratio used when the flow goes 1 -> 2
        const double dp = p1 - p2;
        const double negDp = onNegative(dp), posDp = onPositive(dp);
        const double posR12 = onPositive(-crit + r12), posR21 = onPositive(-crit + r21);
        const double arg12 = (-std::pow(r12, ex1) + std::pow(r12, ex2)) / Ndenom;
        const double arg21 = (-std::pow(r21, ex1) + std::pow(r21, ex2)) / Ndenom;
        // Flow function: 1 when choked, psi(ratio) when sub-critical.
        const double Phi = onNegative(-crit + r12) * negDp + onNegative(-crit + r21) * posDp
                           + negDp * posR12 * signedSquareL(arg12, eps)
                           + posDp * posR21 * signedSquareL(arg21, eps);
        const double dsq12 = dxSignedSquareL(arg12, eps);
        const double dsq21 = dxSignedSquareL(arg21, eps);
        // d(Phi)/dp1 and d(Phi)/dp2 (switches held constant).
        const double dPhi_dp1 =
            (((2.0 * std::pow(r12, -1.0 + ex2)) / (kappa * p2) - (ex1 * std::pow(r12, 1.0 / kappa)) / p2) * dsq12
             * negDp * posR12)
                / Ndenom
            + (((-2.0 * p2 * std::pow(r21, -1.0 + ex2)) / (kappa * (p1 * p1))
                + (ex1 * p2 * std::pow(r21, 1.0 / kappa)) / (p1 * p1))
               * dsq21 * posDp * posR21)
                  / Ndenom;
        const double dPhi_dp2 =
            (((-2.0 * p1 * std::pow(r12, -1.0 + ex2)) / (kappa * (p2 * p2))
              + (ex1 * p1 * std::pow(r12, 1.0 / kappa)) / (p2 * p2))
             * dsq12 * negDp * posR12)
                / Ndenom
            + (((2.0 * std::pow(r21, -1.0 + ex2)) / (kappa * p1) - (ex1 * std::pow(r21, 1.0 / kappa)) / p1) * dsq21
               * posDp * posR21)
                  / Ndenom;
        const double sT1 = std::sqrt(T1), sT2 = std::sqrt(T2);

        mF[0] = qma - (A0 * Cd * Kg * p1 * Phi) / sT1;
        mF[1] = qmb - (A0 * Cd * Kg * p2 * Phi) / sT2;
        mF[2] = qm2 + qmb * negDp - qma * posDp;
        mF[3] = dE1 + cp * qm2 * (T1 * onNegative(-qm2) + T2 * onPositive(-qm2));
        mF[4] = dE2 - cp * qm2 * (T2 * onNegative(qm2) + T1 * onPositive(qm2));
        mF[5] = -c1 + p1 - dE1 * Zc1;
        mF[6] = -c2 + p2 - dE2 * Zc2;

        for (int r = 0; r < 7; ++r) {
            for (int c = 0; c < 7; ++c) { mJ[r][c] = 0.0; }
        }
        mJ[0][0] = 1.0;
        mJ[0][5] = -((A0 * Cd * Kg * p1 * dPhi_dp1) / sT1) - (A0 * Cd * Kg * Phi) / sT1;
        mJ[0][6] = -((A0 * Cd * Kg * p1 * dPhi_dp2) / sT1);
        mJ[1][1] = 1.0;
        mJ[1][5] = -((A0 * Cd * Kg * p2 * dPhi_dp1) / sT2);
        mJ[1][6] = -((A0 * Cd * Kg * p2 * dPhi_dp2) / sT2) - (A0 * Cd * Kg * Phi) / sT2;
        mJ[2][0] = -posDp;
        mJ[2][1] = negDp;
        mJ[2][2] = 1.0;
        mJ[3][2] = cp * (T1 * onNegative(-qm2) + T2 * onPositive(-qm2));
        mJ[3][3] = 1.0;
        mJ[4][2] = -(cp * (T2 * onNegative(qm2) + T1 * onPositive(qm2)));
        mJ[4][4] = 1.0;
        mJ[5][3] = -Zc1;
        mJ[5][5] = 1.0;
        mJ[6][4] = -Zc2;
        mJ[6][6] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("PneumaticOrifice: singular Jacobian in Newton iteration");
            return;
        }
    }

    mQma = mX[0];
    mQmb = mX[1];
    mQm2 = mX[2];
    mDE1 = mX[3];
    mDE2 = mX[4];
    mP1 = mX[5];
    mP2 = mX[6];

    *mPp1.p = mP1;
    *mPp1.qm = -mQm2;
    *mPp1.dE = mDE1;
    *mPp2.p = mP2;
    *mPp2.qm = mQm2;
    *mPp2.dE = mDE2;
    *mpQma = mQma;
    *mpQmb = mQmb;
}

TLMHUB_REGISTER_COMPONENT(PneumaticOrifice, "Pneumatic")

} // namespace tlmhub
