#include "core/components/hydraulic/HydraulicCounterBalanceValveG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicCounterBalanceValveG::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Hydraulic);

    addInputVariable("pref", "Reference pressure", "Pa", 1.0e6, &mp_pref);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mp_rho);
    addInputVariable("visc", "Viscosity (unused)", "Ns/m^2", 0.03, &mp_visc);
    addInputVariable("Dv", "Spool diameter", "m", 0.03, &mp_Dv);
    addInputVariable("frac", "Fraction of spool opening", "-", 0.1, &mp_frac);
    addInputVariable("kappa", "Pilot area fraction", "-", 0.1, &mp_kappa);
    addInputVariable("Bv", "Damping", "N/(m/s)", 100.0, &mp_Bv);
    addInputVariable("Xvmax", "Maximum spool displacement", "m", 0.03, &mp_Xvmax);
    addInputVariable("Cq", "Flow coefficient", "-", 0.67, &mp_Cq);
    addInputVariable("phi", "Jet angle", "rad", 0.03, &mp_phi);
    addInputVariable("ks", "Spring constant", "N/m", 100.0, &mp_ks);
    addInputVariable("p0", "Turbulence onset pressure", "Pa", 1.0e5, &mp_p0);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXvOut);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "visc", "Dv", "frac", "kappa", "Bv", "Xvmax", "Cq", "phi", "ks", "p0"}, false);
}

double HydraulicCounterBalanceValveG::delayedPart() const
{
    const double h = mTimestep;
    return (-(Av * h * p1) + Av * h * p2 - Av * kappa * h * p3 + Av * h * pref - 2.0 * Bv * xv + ks * h * xv + 2.0 * Cq * h * p1 * w * xv * cf - 2.0 * Cq * h * p2 * w * xv * cf) / (2.0 * Bv + ks * h + 2.0 * Cq * h * p1 * w * cf - 2.0 * Cq * h * p2 * w * cf);
}

void HydraulicCounterBalanceValveG::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_p = getSafeNodeDataPtr(mpP3, NodeHydraulic::Pressure);
    mpP3_q = getSafeNodeDataPtr(mpP3, NodeHydraulic::Flow);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeHydraulic::WaveVariable);
    mpP3_Zc = getSafeNodeDataPtr(mpP3, NodeHydraulic::CharImpedance);

    p1 = *mpP1_p; q1 = *mpP1_q; c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    p2 = *mpP2_p; q2 = *mpP2_q; c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    p3 = *mpP3_p; q3 = *mpP3_q; c3 = *mpP3_c; Zc3 = *mpP3_Zc;
    pref = *mp_pref;
    rho = *mp_rho;
    Dv = *mp_Dv;
    frac = *mp_frac;
    kappa = *mp_kappa;
    Bv = *mp_Bv;
    Xvmax = *mp_Xvmax;
    Cq = *mp_Cq;
    phi = *mp_phi;
    ks = *mp_ks;
    p0 = *mp_p0;
    xv = *mpXvOut;

    Av = 0.785398 * Dv * Dv;
    w = 3.14159 * Dv * frac * std::sin(phi);
    cf = std::cos(phi);
    p3 = c3;
    D1 = delayedPart();
}

void HydraulicCounterBalanceValveG::simulateOneTimestep()
{
    const double h = mTimestep;
    c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    c3 = *mpP3_c; Zc3 = *mpP3_Zc;
    pref = *mp_pref; // the only input re-read every step

    Av = 0.785398 * Dv * Dv;
    w = 3.14159 * Dv * frac * std::sin(phi);
    cf = std::cos(phi);
    p3 = c3;
    const double D1prev = D1;

    mX[0] = xv; mX[1] = q2; mX[2] = p1; mX[3] = p2; mX[4] = p3;
    for (int iter = 1; iter <= 2; ++iter) {
        const double N = 2.0 * Bv + ks * h + 2.0 * Cq * h * (p1 - p2) * w * cf;
        const double E = p1 - p2 + kappa * p3 - pref;
        const double Z = Av * h * E / N - D1prev;
        const double G = dxLimit(Z, 0.0, Xvmax);
        const double K = 1.4142135623730951 * Cq * std::sqrt(1.0 / rho) * w;
        const double S = signedSquareL(p1 - p2, p0);
        const double dS = dxSignedSquareL(p1 - p2, p0);
        const double a1 = c1 - q2 * Zc1 * onPositive(p1);
        const double a2 = c2 + q2 * Zc2 * onPositive(p2);

        mF[0] = xv - limit(Z, 0.0, Xvmax);
        mF[1] = q2 - K * xv * S;
        mF[2] = p1 - lowLimit(a1, 0.0);
        mF[3] = p2 - lowLimit(a2, 0.0);
        mF[4] = p3 - lowLimit(c3, 0.0);

        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = -((-2.0 * Av * Cq * (h * h) * E * w * cf / (N * N) + Av * h / N) * G);
        mJ[0][3] = -((2.0 * Av * Cq * (h * h) * E * w * cf / (N * N) - Av * h / N) * G);
        mJ[0][4] = -(Av * kappa * h * G / N);
        mJ[1][0] = -K * S;
        mJ[1][1] = 1.0;
        mJ[1][2] = -K * xv * dS;
        mJ[1][3] = K * xv * dS;
        mJ[1][4] = 0.0;
        mJ[2][0] = 0.0;
        mJ[2][1] = Zc1 * dxLowLimit(a1, 0.0) * onPositive(p1);
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[2][4] = 0.0;
        mJ[3][0] = 0.0;
        mJ[3][1] = -Zc2 * dxLowLimit(a2, 0.0) * onPositive(p2);
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;
        mJ[3][4] = 0.0;
        mJ[4][0] = 0.0;
        mJ[4][1] = 0.0;
        mJ[4][2] = 0.0;
        mJ[4][3] = 0.0;
        mJ[4][4] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicCounterBalanceValveG: singular Jacobian");
        }
        xv = mX[0]; q2 = mX[1]; p1 = mX[2]; p2 = mX[3]; p3 = mX[4];
        q1 = -q2;
        q3 = 0.0;
    }

    D1 = delayedPart();

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP3_p = p3;
    *mpP3_q = q3;
    *mpXvOut = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicCounterBalanceValveG, "Hydraulic")

} // namespace tlmhub
