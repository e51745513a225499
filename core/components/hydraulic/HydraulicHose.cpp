#include "core/components/hydraulic/HydraulicHose.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicHose::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("eta", "Dynamic viscosity", "Ns/m^2", 0.03, &mpVisc);
    addInputVariable("d", "Inner line diameter", "m", 0.03, &mpD);
    addInputVariable("l", "Line length", "m", 1.0, &mpL);
    addConstant("beta_e", "Bulk modulus", "Pa", 1e9, mBetae);
    addConstant("eta_w", "Equivalent wall viscosity", "Ns/m^2", 0.03, mWallVisc);
}

void HydraulicHose::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    const double p1 = *mpP1_p, q1 = *mpP1_q;
    const double p2 = *mpP2_p, q2 = *mpP2_q;
    const double rho = *mpRho;
    const double visc = *mpVisc;
    const double d = *mpD;
    const double l = *mpL;
    const double Ts = mTimestep;

    const double Rtot = 128.0 * visc * l / (pi * d * d * d * d);
    mRL1d = Rtot;
    mRL2d = Rtot;
    mRw = 128.0 * mWallVisc * l / (pi * d * d * d * d);

    const double a = std::sqrt(mBetae / rho);   // speed of sound
    const double TL = l / a;
    mNT = TL / Ts + 0.5;                         // stays real-valued
    mNTMAX = int(mNT + 1);
    mC1i.assign(static_cast<std::size_t>(mNTMAX) + 1, 0.0);
    mC2i.assign(static_cast<std::size_t>(mNTMAX) + 1, 0.0);

    // Zc0 uses the unclamped NT, so it is slightly below rho*a/area.
    mTN = mNT * Ts;
    const double area = pi * d * d / 4.0;
    const double areaC = area * TL / mTN;
    mZc0 = rho * a / areaC;

    if (mNT < 1) mNT = 1;
    mTN = mNT * Ts;

    const double den = 2.0 * mKappa * mNT + 1.0;
    mBC0 = 1.0 / den;
    mBC1 = 1.0 / den;
    mAC1 = -(2.0 * mKappa * mNT - 1.0) / den;

    const double Zc1 = mZc0 + mBC0 * Rtot;
    const double Zc2 = mZc0 + mBC0 * Rtot;

    for (int i = 1; i <= mNTMAX; ++i) {
        mC1i[static_cast<std::size_t>(i)] = p1 + mZc0 * q1;
        mC2i[static_cast<std::size_t>(i)] = p2 + mZc0 * q2;
    }
    mNTIME = 1;

    mRQF1D = Rtot * q1 * (1.0 - mBC0);
    mRQF2D = Rtot * q2 * (1.0 - mBC0);
    mRQEF1D = 0.0;
    mRQEF2D = 0.0;

    const double C1F1 = p1 + mZc0 * q1;
    const double C2F1 = p2 + mZc0 * q2;
    const double c1 = p1 - Zc1 * q1;
    const double c2 = p2 - Zc2 * q2;

    // Placeholder coefficients; the real ones are set every step with setNumDen.
    const double dummy[2] = {0.0, 0.0};
    mFilterC1F.initialize(Ts, dummy, dummy, mC1i[1], mC1i[1]);
    mFilterC2F.initialize(Ts, dummy, dummy, mC2i[1], mC2i[1]);
    mFilterC1F1.initialize(Ts, dummy, dummy, mC1i[1], C1F1);
    mFilterC2F1.initialize(Ts, dummy, dummy, mC2i[1], C2F1);

    *mpP1_c = c1;
    *mpP1_Zc = Zc1;
    *mpP2_c = c2;
    *mpP2_Zc = Zc2;
}

void HydraulicHose::simulateOneTimestep()
{
    const double q1 = *mpP1_q;
    double c1 = *mpP1_c;
    const double q2 = *mpP2_q;
    double c2 = *mpP2_c;
    const double rho = *mpRho;
    const double visc = *mpVisc;
    const double d = *mpD;
    const double l = *mpL;

    // Cyclic memory index.
    mNTIME = mNTIME + 1;
    if (mNTIME > mNTMAX) mNTIME = 1;
    // Read-back slot uses the integer part of NT (uniform int(NT)-1 step lag).
    // Truncating NTIME - NT + 1 as a whole instead (as one public Hopsan source
    // reads) gives a jittery lag and fails HydraulicLineTest.
    int NTIME1 = mNTIME - static_cast<int>(mNT) + 1;
    if (NTIME1 < 1) NTIME1 = NTIME1 + mNTMAX;

    const double RQ1 = rq(mRL1, q1, d, l, rho, visc);
    const double RQ2 = rq(mRL2, q2, d, l, rho, visc);
    mRL1 = (mRL1 + mRL1d) / 2.0;
    mRL2 = (mRL2 + mRL2d) / 2.0;
    mRL1d = mRL1;
    mRL2d = mRL2;
    const double RL = (mRL1 + mRL2) / 2.0;

    const double Zc1 = mZc0 + mBC0 * mRL1;
    const double Zc2 = mZc0 + mBC0 * mRL2;

    mC1i[static_cast<std::size_t>(mNTIME)] = c1 + 2.0 * mZc0 * q1;
    mC2i[static_cast<std::size_t>(mNTIME)] = c2 + 2.0 * mZc0 * q2;

    // Low-pass filtering of the transmitted characteristics.
    const double W1 = 1.0 / (mKappa * mTN);
    const double W2 = W1 * std::exp(RL / (2.0 * mZc0));
    const double W3 = mRw / (2.0 * mZc0 * mTN);
    const double W4 = W3 * std::exp(mRw / (2.0 * mZc0));

    const double numF[2] = {1.0, 1.0 / W2};
    const double denF[2] = {1.0, 1.0 / W1};
    const double numF1[2] = {1.0, 1.0 / W4};
    const double denF1[2] = {1.0, 1.0 / W3};
    mFilterC1F.setNumDen(numF, denF);
    const double C1F = mFilterC1F.update(mC1i[static_cast<std::size_t>(NTIME1)]);
    mFilterC2F.setNumDen(numF, denF);
    const double C2F = mFilterC2F.update(mC2i[static_cast<std::size_t>(NTIME1)]);
    mFilterC1F1.setNumDen(numF1, denF1);
    const double C1F1 = mFilterC1F1.update(C1F);
    mFilterC2F1.setNumDen(numF1, denF1);
    const double C2F1 = mFilterC2F1.update(C2F);

    // Friction terms.
    mRQF1D = mRQF1D + mBC0 * mRL1 * q1;
    mRQF2D = mRQF2D + mBC0 * mRL2 * q2;
    const double RQF1 = -mAC1 * mRQF1D + mBC1 * mRL1 * q1;
    const double RQF2 = -mAC1 * mRQF2D + mBC1 * mRL2 * q2;
    mRQF1D = RQF1;
    mRQF2D = RQF2;
    const double RQEF1 = -mAC1 * mRQEF1D + (mBC0 + mBC1) * (RQ1 - mRL1 * q1);
    const double RQEF2 = -mAC1 * mRQEF2D + (mBC0 + mBC1) * (RQ2 - mRL2 * q2);
    mRQEF1D = RQEF1;
    mRQEF2D = RQEF2;

    // New characteristics (grouping BC0*(-RL*q) as in Hopsan).
    c1 = C2F1 + RQF1 + mBC0 * (-mRL1 * q1) + RQEF1;
    c2 = C1F1 + RQF2 + mBC0 * (-mRL2 * q2) + RQEF2;

    *mpP1_c = c1;
    *mpP1_Zc = Zc1;
    *mpP2_c = c2;
    *mpP2_Zc = Zc2;
}

// Friction factorisation: returns the friction pressure drop and sets the
// equivalent linear resistance RL (laminar below Re 2300, Blasius above).
double HydraulicHose::rq(double& RL, double Q, double D, double L, double rho, double visc)
{
    const double RE = std::fabs(4 * rho * Q / (pi * D * visc));
    if (RE < 2300) {
        RL = 128 * visc * L / (pi * D * D * D * D);
        return RL * Q;
    }
    const double F = 0.079 * std::pow(RE, -0.25);
    RL = 1.75 * 32 * rho * F * L * std::fabs(Q) / (pi * pi * D * D * D * D * D);
    return 32 * rho * F * L * std::fabs(Q) * Q / (pi * pi * D * D * D * D * D);
}

TLMHUB_REGISTER_COMPONENT(HydraulicHose, "Hydraulic")

} // namespace tlmhub
