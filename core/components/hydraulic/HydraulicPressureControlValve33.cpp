#include "core/components/hydraulic/HydraulicPressureControlValve33.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicPressureControlValve33::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Hydraulic);
    mpP4 = addPowerPort("P4", NodeType::Hydraulic);

    addInputVariable("pref", "Reference pressure", "Pa", 1.0e6, &mp_pref);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mp_rho);
    addInputVariable("Cq", "Flow coefficient", "-", 0.67, &mp_Cq);
    addInputVariable("Sd", "Spool diameter", "m", 0.01, &mp_Sd);
    addInputVariable("Frap", "Circumference fraction P-A", "-", 1.0, &mp_Frap);
    addInputVariable("Frat", "Circumference fraction A-T", "-", 1.0, &mp_Frat);
    addInputVariable("Xap0", "Underlap P-A", "m", 0.0, &mp_Xap0);
    addInputVariable("Xat0", "Underlap A-T", "m", 0.0, &mp_Xat0);
    addInputVariable("plam", "Turbulence onset pressure", "Pa", 1.0e4, &mp_plam);
    addInputVariable("Bv", "Damping", "N/(m/s)", 100.0, &mp_Bv);
    addInputVariable("Xvmin", "Minimum spool displacement", "m", -0.01, &mp_Xvmin);
    addInputVariable("Xvmax", "Maximum spool displacement", "m", 0.01, &mp_Xvmax);
    addInputVariable("phi", "Jet angle", "rad", 0.03, &mp_phi);
    addInputVariable("ks", "Spring constant", "N/m", 100.0, &mp_ks);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mp_xv);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "Cq", "Sd", "Frap", "Frat", "Xap0", "Xat0", "plam", "Bv", "Xvmin", "Xvmax",
                      "phi", "ks"}, false);
}

void HydraulicPressureControlValve33::localExpressions()
{
    Ks = 1.4142135623730951 * Cq / std::sqrt(rho);
    Av = 0.785398 * (Sd * Sd);
    cf = std::cos(phi);
    p4 = c4;
}

double HydraulicPressureControlValve33::delayedPart() const
{
    const double h = mTimestep;
    const double Opa = onPositive(limit(Xap0 + xv, 0.0, Xap0 + Xvmax));
    const double Oat = onPositive(limit(-Xat0 - xv, 0.0, -Xat0 - Xvmin));
    return (-Av * h * p4 + Av * h * pref - 2.0 * Bv * xv + ks * h * xv
            + 6.28319 * Cq * Frat * h * Sd * xv * std::fabs(p3 - p2) * cf * Oat
            + 6.28319 * Cq * Frap * h * Sd * xv * std::fabs(p1 - p3) * cf * Opa)
           / (2.0 * Bv + ks * h + 6.28319 * Cq * Frat * h * Sd * std::fabs(p3 - p2) * cf * Oat
              + 6.28319 * Cq * Frap * h * Sd * std::fabs(p1 - p3) * cf * Opa);
}

void HydraulicPressureControlValve33::initialize()
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
    mpP4_p = getSafeNodeDataPtr(mpP4, NodeHydraulic::Pressure);
    mpP4_q = getSafeNodeDataPtr(mpP4, NodeHydraulic::Flow);
    mpP4_c = getSafeNodeDataPtr(mpP4, NodeHydraulic::WaveVariable);
    mpP4_Zc = getSafeNodeDataPtr(mpP4, NodeHydraulic::CharImpedance);

    p1 = *mpP1_p; q1 = *mpP1_q; c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    p2 = *mpP2_p; q2 = *mpP2_q; c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    p3 = *mpP3_p; q3 = *mpP3_q; c3 = *mpP3_c; Zc3 = *mpP3_Zc;
    p4 = *mpP4_p; q4 = *mpP4_q; c4 = *mpP4_c; Zc4 = *mpP4_Zc;
    pref = *mp_pref;
    rho = *mp_rho;
    Cq = *mp_Cq;
    Sd = *mp_Sd;
    Frap = *mp_Frap;
    Frat = *mp_Frat;
    Xap0 = *mp_Xap0;
    Xat0 = *mp_Xat0;
    plam = *mp_plam;
    Bv = *mp_Bv;
    Xvmin = *mp_Xvmin;
    Xvmax = *mp_Xvmax;
    phi = *mp_phi;
    ks = *mp_ks;
    xv = *mp_xv;
    localExpressions();
    D1 = delayedPart();
}

void HydraulicPressureControlValve33::simulateOneTimestep()
{
    c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    c3 = *mpP3_c; Zc3 = *mpP3_Zc;
    c4 = *mpP4_c; Zc4 = *mpP4_Zc;
    pref = *mp_pref;
    localExpressions();
    const double D1prev = D1;

    mX[0] = xv; mX[1] = q1; mX[2] = q2; mX[3] = q3; mX[4] = p1; mX[5] = p2; mX[6] = p3;
    for (int iter = 1; iter <= 2; ++iter) {
        const double h = mTimestep;
        const double Lpa = limit(Xap0 + xv, 0.0, Xap0 + Xvmax);
        // A-T opening uses Xap0 inside the limit (reference quirk, as HydraulicValve33).
        const double Lat = limit(Xap0 - xv, 0.0, Xat0 + Xvmax);
        const double Opa = onPositive(limit(Xap0 + xv, 0.0, Xap0 + Xvmax));
        const double Oat = onPositive(limit(-Xat0 - xv, 0.0, -Xat0 - Xvmin));
        const double N = 2.0 * Bv + ks * h + 6.28319 * Cq * Frat * h * Sd * std::fabs(p2 - p3) * cf * Oat
                         + 6.28319 * Cq * Frap * h * Sd * std::fabs(p1 - p3) * cf * Opa;
        const double P = pref - p4;
        const double Z = -(Av * h * (pref - p4) / N) - D1prev;
        const double G = dxLimit(Z, Xvmin, Xvmax);
        const double S13 = signedSquareL(p1 - p3, plam);
        const double S23 = signedSquareL(p2 - p3, plam);
        const double dS13 = dxSignedSquareL(p1 - p3, plam);
        const double dS23 = dxSignedSquareL(p2 - p3, plam);
        const double dLpa = dxLimit(Xap0 + xv, 0.0, Xap0 + Xvmax);
        const double dLat = dxLimit(Xap0 - xv, 0.0, Xat0 + Xvmax);
        const double a1 = c1 + q1 * Zc1 * onPositive(p1);
        const double a2 = c2 + q2 * Zc2 * onPositive(p2);
        const double a3 = c3 + q3 * Zc3 * onPositive(p3);

        mF[0] = xv - limit(Z, Xvmin, Xvmax);
        mF[1] = q1 + 3.14159 * Frap * Ks * Sd * Lpa * S13;
        mF[2] = q2 + 3.14159 * Frat * Ks * Sd * Lat * S23;
        mF[3] = q3 + Ks * Sd * (-3.14159 * Frap * Lpa * S13 - 3.14159 * Frat * Lat * S23);
        mF[4] = p1 - lowLimit(a1, 0.0);
        mF[5] = p2 - lowLimit(a2, 0.0);
        mF[6] = p3 - lowLimit(a3, 0.0);

        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = 0.0;
        mJ[0][3] = 0.0;
        mJ[0][4] = (-6.28319 * Av * Cq * Frap * (h * h) * P * Sd * cf * dxAbs(p1 - p3) * G * Opa) / (N * N);
        mJ[0][5] = (-6.28319 * Av * Cq * Frat * (h * h) * P * Sd * cf * dxAbs(p2 - p3) * G * Oat) / (N * N);
        mJ[0][6] = -(Av * h * P * G * (-6.28319 * Cq * Frat * h * Sd * cf * dxAbs(p2 - p3) * Oat - 6.28319 * Cq * Frap * h * Sd * cf * dxAbs(p1 - p3) * Opa)) / (N * N);
        mJ[1][0] = 3.14159 * Frap * Ks * Sd * dLpa * S13;
        mJ[1][1] = 1.0;
        mJ[1][2] = 0.0;
        mJ[1][3] = 0.0;
        mJ[1][4] = 3.14159 * Frap * Ks * Sd * dS13 * Lpa;
        mJ[1][5] = 0.0;
        mJ[1][6] = -3.14159 * Frap * Ks * Sd * dS13 * Lpa;
        mJ[2][0] = -3.14159 * Frat * Ks * Sd * dLat * S23;
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[2][4] = 0.0;
        mJ[2][5] = 3.14159 * Frat * Ks * Sd * dS23 * Lat;
        mJ[2][6] = -3.14159 * Frat * Ks * Sd * dS23 * Lat;
        mJ[3][0] = Ks * Sd * (-3.14159 * Frap * dLpa * S13 + 3.14159 * Frat * dLat * S23);
        mJ[3][1] = 0.0;
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;
        mJ[3][4] = -3.14159 * Frap * Ks * Sd * dS13 * Lpa;
        mJ[3][5] = -3.14159 * Frat * Ks * Sd * dS23 * Lat;
        mJ[3][6] = Ks * Sd * (3.14159 * Frat * dS23 * Lat + 3.14159 * Frap * dS13 * Lpa);
        mJ[4][0] = 0.0;
        mJ[4][1] = -Zc1 * dxLowLimit(a1, 0.0) * onPositive(p1);
        mJ[4][2] = 0.0;
        mJ[4][3] = 0.0;
        mJ[4][4] = 1.0;
        mJ[4][5] = 0.0;
        mJ[4][6] = 0.0;
        mJ[5][0] = 0.0;
        mJ[5][1] = 0.0;
        mJ[5][2] = -Zc2 * dxLowLimit(a2, 0.0) * onPositive(p2);
        mJ[5][3] = 0.0;
        mJ[5][4] = 0.0;
        mJ[5][5] = 1.0;
        mJ[5][6] = 0.0;
        mJ[6][0] = 0.0;
        mJ[6][1] = 0.0;
        mJ[6][2] = 0.0;
        mJ[6][3] = -Zc3 * dxLowLimit(a3, 0.0) * onPositive(p3);
        mJ[6][4] = 0.0;
        mJ[6][5] = 0.0;
        mJ[6][6] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicPressureControlValve33: singular Jacobian");
        }
        xv = mX[0]; q1 = mX[1]; q2 = mX[2]; q3 = mX[3]; p1 = mX[4]; p2 = mX[5]; p3 = mX[6];
        p4 = c4;
    }
    D1 = delayedPart();

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP3_p = p3;
    *mpP3_q = q3;
    *mpP4_p = p4;
    *mpP4_q = q4;
    *mp_xv = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlValve33, "Hydraulic")

} // namespace tlmhub
