#include "core/components/hydraulic/HydraulicAckumulator.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicAckumulator::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("V0", "Total accumulator volume", "m^3", 0.001, &mpV0);
    addInputVariable("Kca", "Inlet flow-pressure coefficient", "m^3/(s Pa)", 1e-8, &mpKca);
    addInputVariable("kappa", "Polytropic exponent of the gas", "", 1.2, &mpKappa);
    addInputVariable("p0", "Gas pre-charge pressure", "Pa", 1e7, &mpP0);
    addOutputVariable("Va", "Momentary gas volume", "m^3", 0.001, &mpVa);
    addOutputVariable("pa", "Gas pressure", "Pa", 1e7, &mpPa);
    addOutputVariable("xmp", "State of charge (oil fraction)", "", 0.0, &mpXmp);
    addOutputVariable("vmp", "Rate of change of xmp", "1/s", 0.0, &mpVmp);
}

void HydraulicAckumulator::initialize()
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

    const double V0 = *mpV0;
    const double Kca = *mpKca;
    const double Ts = mTimestep;
    mD = (-(Kca * Ts * mP1 * V0) + Kca * Ts * mPa * V0 - 2 * std::pow(V0, 2) * mXmp) / (2 * std::pow(V0, 2));

    // One full step (node writes included) already during initialisation.
    simulateOneTimestep();
}

void HydraulicAckumulator::simulateOneTimestep()
{
    const double c1 = *mpP1_c;
    const double Zc1 = *mpP1_Zc;
    const double V0 = *mpV0;
    const double Kca = *mpKca;
    const double kappa = *mpKappa;
    const double p0 = *mpP0;
    const double Ts = mTimestep;

    mX[0] = mVmp;
    mX[1] = mXmp;
    mX[2] = mQ1;
    mX[3] = mPa;
    mX[4] = mP1;

    for (int iter = 1; iter <= 2; ++iter) {
        const double vmp = mX[0], xmp = mX[1], q1 = mX[2], pa = mX[3], p1 = mX[4];
        const double A = Kca * Ts * (p1 - pa) / (2 * V0) - mD;
        const double X = limit(A, 0, 1);

        mF[0] = vmp + Kca * (pa - p1) * dxLimit(X, 0, 1) / V0;
        mF[1] = xmp - X;
        mF[2] = q1 + V0 * vmp;
        mF[3] = pa - p0 * std::pow(V0, kappa) / std::pow(V0 * limit(1 - xmp, 0.1, 1), kappa);
        mF[4] = p1 - lowLimit(c1 + q1 * Zc1 * onPositive(p1), 0);

        for (int r = 0; r < 5; ++r) {
            for (int k = 0; k < 5; ++k) { mJ[r][k] = 0.0; }
        }
        mJ[0][0] = 1;
        mJ[0][3] = Kca * dxLimit(X, 0, 1) / V0;
        mJ[0][4] = -(Kca * dxLimit(X, 0, 1) / V0);
        mJ[1][1] = 1;
        mJ[1][3] = Kca * Ts * dxLimit(A, 0, 1) / (2 * V0);
        mJ[1][4] = -(Kca * Ts * dxLimit(A, 0, 1) / (2 * V0));
        mJ[2][0] = V0;
        mJ[2][2] = 1;
        mJ[3][1] = -(kappa * p0 * std::pow(V0, 1 + kappa) * dxLimit(1 - xmp, 0.1, 1)
                     * std::pow(V0 * limit(1 - xmp, 0.1, 1), -1 - kappa));
        mJ[3][3] = 1;
        mJ[4][2] = -(Zc1 * dxLowLimit(c1 + q1 * Zc1 * onPositive(p1), 0) * onPositive(p1));
        mJ[4][4] = 1;

        mSolver.solve(mJ, mF, mX, iter);

        mVmp = mX[0];
        mXmp = mX[1];
        mQ1 = mX[2];
        mPa = mX[3];
        mP1 = mX[4];
        mVa = V0 * (1 - mXmp);
    }

    mD = (-(Kca * Ts * mP1 * V0) + Kca * Ts * mPa * V0 - 2 * std::pow(V0, 2) * mXmp) / (2 * std::pow(V0, 2));

    *mpP1_p = mP1;
    *mpP1_q = mQ1;
    *mpP1_dE = mDE1;
    *mpVa = mVa;
    *mpPa = mPa;
    *mpXmp = mXmp;
    *mpVmp = mVmp;
}

TLMHUB_REGISTER_COMPONENT(HydraulicAckumulator, "Hydraulic")

} // namespace tlmhub
