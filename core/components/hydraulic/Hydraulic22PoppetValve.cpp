#include "core/components/hydraulic/Hydraulic22PoppetValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void Hydraulic22PoppetValve::configure()
{
    mpPN = addPowerPort("PN", NodeType::Hydraulic);
    mpPS = addPowerPort("PS", NodeType::Hydraulic);
    mpPC = addPowerPort("PC", NodeType::Hydraulic);

    addOutputVariable("xv_out", "Spool position", "", 0.0, &mpXv);
    addInputVariable("C_q", "Flow Coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil Density", "kg/m^3", 890.0, &mpRho);
    addInputVariable("d_1", "Small diameter", "m", 10e-3, &mpD1);
    addInputVariable("d_2", "Big diameter", "m", 10e-3, &mpD2);
    addInputVariable("k", "Spring constant", "N/m", 1e4, &mpK);
    addInputVariable("F_0", "Spring pre-load", "N", 100.0, &mpF0);
    addInputVariable("f", "Fraction of poppet diameter that is opening", "-", 1.0, &mpF);
    addConstant("x_vmax", "Maximum Spool Displacement", "m", 0.01, mXvmax);
    addConstant("d_d", "Damp orifice diam.", "m", 0.1e-3, mDd);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"d_2"}, false);
}

void Hydraulic22PoppetValve::initialize()
{
    mpPN_p = getSafeNodeDataPtr(mpPN, NodeHydraulic::Pressure);
    mpPN_q = getSafeNodeDataPtr(mpPN, NodeHydraulic::Flow);
    mpPN_c = getSafeNodeDataPtr(mpPN, NodeHydraulic::WaveVariable);
    mpPN_Zc = getSafeNodeDataPtr(mpPN, NodeHydraulic::CharImpedance);
    mpPS_p = getSafeNodeDataPtr(mpPS, NodeHydraulic::Pressure);
    mpPS_q = getSafeNodeDataPtr(mpPS, NodeHydraulic::Flow);
    mpPS_c = getSafeNodeDataPtr(mpPS, NodeHydraulic::WaveVariable);
    mpPS_Zc = getSafeNodeDataPtr(mpPS, NodeHydraulic::CharImpedance);
    mpPC_p = getSafeNodeDataPtr(mpPC, NodeHydraulic::Pressure);
    mpPC_q = getSafeNodeDataPtr(mpPC, NodeHydraulic::Flow);
    mpPC_c = getSafeNodeDataPtr(mpPC, NodeHydraulic::WaveVariable);
    mpPC_Zc = getSafeNodeDataPtr(mpPC, NodeHydraulic::CharImpedance);

    // Areas are fixed at start: seat (N), annulus (S) and back face (C).
    mAN = pi * *mpD1 * *mpD1 / 4.0;
    mAC = pi * *mpD2 * *mpD2 / 4.0;
    mAS = mAC - mAN;

    mX.initialize(mTimestep, 0.0, limit(*mpXv, 0.0, mXvmax), 0.0, mXvmax);
    mQDamp.setFlowCoefficient(*mpCq * pi * mDd * mDd / 4.0 * std::sqrt(2.0 / *mpRho));
}

void Hydraulic22PoppetValve::simulateOneTimestep()
{
    double cN = *mpPN_c, ZcN = *mpPN_Zc;
    double cS = *mpPS_c, ZcS = *mpPS_Zc;
    double cC = *mpPC_c, ZcC = *mpPC_Zc;
    const double rho = *mpRho, Cq = *mpCq, F0 = *mpF0, k = *mpK;
    const double x = mX.value();

    mQSeat.setFlowCoefficient(Cq * pi * *mpD1 * *mpF * x * std::sqrt(2.0 / rho));

    // Seat flow S -> N, then the chamber pressure that balances the poppet; the
    // damping orifice flow between that pressure and PC moves the poppet.
    double qN = mQSeat.getFlow(cS, cN, ZcS, ZcN);
    double qS = -qN;
    double pN = cN + ZcN * qN;
    double pS = cS + ZcS * qS;
    double pChamber = (mAN * pN + mAS * pS - (F0 + k * x)) / mAC;
    const double qC = mQDamp.getFlow(pChamber, cC, 0.0, ZcC);
    const double pC = cC + ZcC * qC;
    double v = qC / mAC;

    bool cav = false;
    if (pN < 0.0) { cN = 0.0; ZcN = 0.0; cav = true; }
    if (pS < 0.0) { cS = 0.0; ZcS = 0.0; cav = true; }
    if (pC < 0.0) { cC = 0.0; ZcC = 0.0; cav = true; }
    if (cav) {
        // As Hopsan: the retry updates the seat side and the poppet velocity,
        // while PC keeps the pressure and flow of the first pass.
        qN = mQSeat.getFlow(cS, cN, ZcS, ZcN);
        qS = -qN;
        pN = cN + ZcN * qN;
        pS = cS + ZcS * qS;
        pChamber = (mAN * pN + mAS * pS - (F0 + k * x)) / mAC;
        v = mQDamp.getFlow(pChamber, cC, 0.0, ZcC) / mAC;
    }

    mX.update(v);

    *mpPN_p = pN;
    *mpPN_q = qN;
    *mpPS_p = pS;
    *mpPS_q = qS;
    *mpPC_p = pC;
    *mpPC_q = qC;
    *mpXv = mX.value();
}

TLMHUB_REGISTER_COMPONENT(Hydraulic22PoppetValve, "Hydraulic")

} // namespace tlmhub
