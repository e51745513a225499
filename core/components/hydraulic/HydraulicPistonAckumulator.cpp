#include "core/components/hydraulic/HydraulicPistonAckumulator.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicPistonAckumulator::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("Ap", "Piston area", "m^2", 0.001, &mpAp);
    addInputVariable("SL", "Stroke", "m", 0.5, &mpSL);
    addInputVariable("Bp", "Viscous friction coefficient", "N s/m", 10.0, &mpBp);
    addInputVariable("ML", "Piston mass", "kg", 1.0, &mpML);
    addInputVariable("kappa", "Polytropic exponent of the gas", "", 1.2, &mpKappa);
    addInputVariable("p0", "Gas pre-charge pressure", "Pa", 1e7, &mpP0);
    addOutputVariable("Va", "Gas volume", "m^3", 0.001, &mpVa);
    addOutputVariable("pa", "Gas pressure", "Pa", 1e7, &mpPa);
    addOutputVariable("xmp", "Piston position", "m", 0.0, &mpXmp);
    addOutputVariable("vmp", "Piston speed", "m/s", 0.0, &mpVmp);
}

void HydraulicPistonAckumulator::computeDelayedTerms(double& D11, double& D12, double& D21) const
{
    const double Ap = *mpAp;
    const double Bp = *mpBp;
    const double ML = *mpML;
    const double Ts = mTimestep;
    const double den2 = 4 * ML + 2 * Bp * Ts;
    const double den1 = 2 * ML + Bp * Ts;
    D11 = (-2 * Ap * std::pow(Ts, 2) * mP1 + 2 * Ap * std::pow(Ts, 2) * mPa - 8 * ML * mXmp) / den2;
    D12 = (-(Ap * std::pow(Ts, 2) * mP1) + Ap * std::pow(Ts, 2) * mPa + 4 * ML * mXmp - 2 * Bp * Ts * mXmp) / den2;
    D21 = (-(Ap * Ts * mP1) + Ap * Ts * mPa - 2 * ML * mVmp + Bp * Ts * mVmp) / den1;
}

void HydraulicPistonAckumulator::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeHydraulic::Temperature);
    mpP1_dE = getSafeNodeDataPtr(mpP1, NodeHydraulic::HeatFlow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);

    mP1 = *mpP1_p;
    mQ1 = *mpP1_q;
    mDE1 = *mpP1_dE;
    mVa = *mpVa;
    mPa = *mpPa;
    mXmp = *mpXmp;
    mVmp = *mpVmp;

    double D11 = 0.0, D12 = 0.0, D21 = 0.0;
    computeDelayedTerms(D11, D12, D21);
    mD12Newest = D12;   // buffer seeded with D12 in every slot
    mDx1 = D11;
    mDx2 = D12;
    mDv = D21;

    simulateOneTimestep();
}

void HydraulicPistonAckumulator::simulateOneTimestep()
{
    const double c1 = *mpP1_c;
    const double Zc1 = *mpP1_Zc;
    const double Ap = *mpAp;
    const double SL = *mpSL;
    const double Bp = *mpBp;
    const double ML = *mpML;
    const double kappa = *mpKappa;
    const double p0 = *mpP0;
    const double Ts = mTimestep;

    mX[0] = mXmp;
    mX[1] = mVmp;
    mX[2] = mQ1;
    mX[3] = mPa;
    mX[4] = mP1;

    for (int iter = 1; iter <= 2; ++iter) {
        const double xmp = mX[0], vmp = mX[1], q1 = mX[2], pa = mX[3], p1 = mX[4];
        const double A = Ap * std::pow(Ts, 2) * (p1 - pa) / (4 * ML + 2 * Bp * Ts) - mDx1 - mDx2;
        const double X = limit(A, 0, SL);

        mF[0] = xmp - X;
        mF[1] = vmp - dxLimit(X, 0, SL) * (-(Ap * Ts * (pa - p1)) / (2 * ML + Bp * Ts) - mDv);
        mF[2] = q1 + Ap * vmp;
        mF[3] = pa - p0 * std::pow(Ap * SL, kappa) / std::pow(Ap * limit(SL - xmp, 0.001 * SL, SL), kappa);
        mF[4] = p1 - lowLimit(c1 + q1 * Zc1, 0);

        for (int r = 0; r < 5; ++r) {
            for (int k = 0; k < 5; ++k) { mJ[r][k] = 0.0; }
        }
        const double J03 = Ap * std::pow(Ts, 2) * dxLimit(A, 0, SL) / (4 * ML + 2 * Bp * Ts);
        const double J13 = Ap * Ts * dxLimit(X, 0, SL) / (2 * ML + Bp * Ts);
        mJ[0][0] = 1;
        mJ[0][3] = J03;
        mJ[0][4] = -J03;
        mJ[1][1] = 1;
        mJ[1][3] = J13;
        mJ[1][4] = -J13;
        mJ[2][1] = Ap;
        mJ[2][2] = 1;
        mJ[3][0] = -(Ap * kappa * p0 * std::pow(Ap * SL, kappa) * dxLimit(SL - xmp, 0.001 * SL, SL)
                     * std::pow(Ap * limit(SL - xmp, 0.001 * SL, SL), -1 - kappa));
        mJ[3][3] = 1;
        mJ[4][2] = -(Zc1 * dxLowLimit(c1 + q1 * Zc1, 0));
        mJ[4][4] = 1;

        mSolver.solve(mJ, mF, mX, iter);

        mXmp = mX[0];
        mVmp = mX[1];
        mQ1 = mX[2];
        mPa = mX[3];
        mP1 = mX[4];
        mVa = Ap * (SL - mXmp);
    }

    double D11 = 0.0, D12 = 0.0, D21 = 0.0;
    computeDelayedTerms(D11, D12, D21);
    mDx1 = D11;
    mDx2 = mD12Newest;   // D12 of the previous step (two steps back next time it is used)
    mDv = D21;
    mD12Newest = D12;

    *mpP1_p = mP1;
    *mpP1_q = mQ1;
    *mpP1_dE = mDE1;
    *mpVa = mVa;
    *mpPa = mPa;
    *mpXmp = mXmp;
    *mpVmp = mVmp;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPistonAckumulator, "Hydraulic")

} // namespace tlmhub
