#include "core/components/hydraulic/HydraulicPressureReliefValveG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicPressureReliefValveG::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);

    addInputVariable("pref", "Reference (opening) pressure", "Pa", 1.0e7, &mpPref);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("visc", "Viscosity (unused)", "Ns/m^2", 0.03, &mpVisc);
    addInputVariable("Dv", "Spool diameter", "m", 0.01, &mpDv);
    addInputVariable("frac", "Fraction of spool opening", "-", 0.1, &mpFrac);
    addInputVariable("Bv", "Damping", "N/(m/s)", 1000.0, &mpBv);
    addInputVariable("Xvmax", "Maximum spool displacement", "m", 0.002, &mpXvmax);
    addInputVariable("Cq", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("phi", "Jet angle", "rad", 1.17, &mpPhi);
    addInputVariable("ks", "Spring constant", "N/m", 10000.0, &mpKs);
    addInputVariable("p0", "Turbulence onset pressure", "Pa", 1.0e5, &mpP0);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXvOut);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "visc", "Dv", "frac", "Bv", "Xvmax", "Cq", "phi", "ks", "p0"}, false);
}

double HydraulicPressureReliefValveG::delayedPart() const
{
    const double h = mTimestep;
    return (-(Av * h * p1) + Av * h * p2 + Av * h * pref - 2.0 * Bv * xv + ke * h * xv) / (2.0 * Bv + ke * h);
}

void HydraulicPressureReliefValveG::initialize()
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
    pref = *mpPref; rho = *mpRho; Dv = *mpDv; frac = *mpFrac; Bv = *mpBv;
    Xvmax = *mpXvmax; Cq = *mpCq; phi = *mpPhi; ks = *mpKs; p0 = *mpP0;
    xv = *mpXvOut;

    Av = 0.785398 * Dv * Dv;
    w = 3.14159 * Dv * frac * std::sin(phi);
    kf = 2.0 * Cq * (p1 - p2) * w * std::cos(phi);
    ke = kf + ks;
    D1 = delayedPart();
}

void HydraulicPressureReliefValveG::simulateOneTimestep()
{
    const double h = mTimestep;
    c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    pref = *mpPref; // the only input re-read every step

    // Flow-force stiffness from the previous step's pressures.
    Av = 0.785398 * Dv * Dv;
    w = 3.14159 * Dv * frac * std::sin(phi);
    kf = 2.0 * Cq * (p1 - p2) * w * std::cos(phi);
    ke = kf + ks;
    const double D1prev = D1;

    mX[0] = xv; mX[1] = q2; mX[2] = p1; mX[3] = p2;
    for (int iter = 1; iter <= 2; ++iter) {
        const double Z = -(Av * h * (-p1 + p2 + pref)) / (2.0 * Bv + ke * h) - D1prev;
        const double G = dxLimit(Z, 0.0, Xvmax);
        const double K = 1.4142135623730951 * Cq * std::sqrt(1.0 / rho) * w;
        const double S = signedSquareL(p1 - p2, p0);
        const double dS = dxSignedSquareL(p1 - p2, p0);

        mF[0] = xv - limit(Z, 0.0, Xvmax);
        mF[1] = q2 - K * xv * S;
        mF[2] = p1 - lowLimit(c1 - q2 * Zc1, 0.0);
        mF[3] = p2 - lowLimit(c2 + q2 * Zc2, 0.0);

        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = -(Av * h * G) / (2.0 * Bv + ke * h);
        mJ[0][3] = (Av * h * G) / (2.0 * Bv + ke * h);
        mJ[1][0] = -K * S;
        mJ[1][1] = 1.0;
        mJ[1][2] = -K * xv * dS;
        mJ[1][3] = K * xv * dS;
        mJ[2][0] = 0.0;
        mJ[2][1] = Zc1 * dxLowLimit(c1 - q2 * Zc1, 0.0);
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[3][0] = 0.0;
        mJ[3][1] = -Zc2 * dxLowLimit(c2 + q2 * Zc2, 0.0);
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicPressureReliefValveG: singular Jacobian");
        }
        xv = mX[0]; q2 = mX[1]; p1 = mX[2]; p2 = mX[3];
        q1 = -q2;
    }

    D1 = delayedPart();

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpXvOut = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureReliefValveG, "Hydraulic")

} // namespace tlmhub
