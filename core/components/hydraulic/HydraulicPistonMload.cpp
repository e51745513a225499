#include "core/components/hydraulic/HydraulicPistonMload.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void HydraulicPistonMload::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPmp = addPowerPort("Pmp", NodeType::Mechanic);

    addInputVariable("A1", "Piston area 1", "m^2", 0.001, &mp_A1);
    addInputVariable("A2", "Piston area 2", "m^2", 0.001, &mp_A2);
    addInputVariable("SL", "Stroke (unused)", "m", 0.5, &mp_SL);
    addInputVariable("Cip", "Internal leakage coefficient", "m^3/(s Pa)", 0.0, &mp_Cip);
    addInputVariable("bp", "Piston viscous friction", "N/(m/s)", 0.0, &mp_bp);
    addInputVariable("mL", "Load mass", "kg", 1000.0, &mp_mL);
    addInputVariable("bL", "Load viscous friction", "Ns/m", 0.0, &mp_bL);
    addInputVariable("fc", "Dry friction", "N", 10.0, &mp_fc);
    addInputVariable("bfc", "Numerical friction factor", "-", 1.0, &mp_bfc);
    addInputVariable("xmin", "Lower stroke limit", "m", 0.0, &mp_xmin);
    addInputVariable("xmax", "Upper stroke limit", "m", 0.5, &mp_xmax);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"A1", "A2", "SL", "Cip", "bp", "mL", "bL", "fc", "bfc", "xmin", "xmax"}, false);
}

void HydraulicPistonMload::delayedParts(double& D11, double& D12, double& D21) const
{
    const double h = mTimestep;
    D11 = (-2.0 * A1 * c1 * (h * h) + 2.0 * A2 * c2 * (h * h) + 2.0 * cmp * (h * h) + 2.0 * bL * (h * h) * vmp + 2.0 * bp * (h * h) * vmp - 8.0 * mL * xmp - 2.0 * A1 * (h * h) * q1 * Zc1 + 2.0 * A2 * (h * h) * q2 * Zc2 + 2.0 * (h * h) * vmp * Zcmp) / (4.0 * mL);
    D12 = (-(A1 * c1 * (h * h)) + A2 * c2 * (h * h) + cmp * (h * h) + bL * (h * h) * vmp + bp * (h * h) * vmp + 4.0 * mL * xmp - A1 * (h * h) * q1 * Zc1 + A2 * (h * h) * q2 * Zc2 + (h * h) * vmp * Zcmp) / (4.0 * mL);
    D21 = (-(A1 * c1 * h) + A2 * c2 * h + cmp * h - 2.0 * mL * vmp + bL * h * vmp + bp * h * vmp - A1 * h * q1 * Zc1 + A2 * h * q2 * Zc2 + h * vmp * Zcmp) / (2.0 * mL + bL * h + bp * h + h * Zcmp);
}

void HydraulicPistonMload::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPmp_f = getSafeNodeDataPtr(mpPmp, NodeMechanic::Force);
    mpPmp_x = getSafeNodeDataPtr(mpPmp, NodeMechanic::Position);
    mpPmp_v = getSafeNodeDataPtr(mpPmp, NodeMechanic::Velocity);
    mpPmp_c = getSafeNodeDataPtr(mpPmp, NodeMechanic::WaveVariable);
    mpPmp_Zc = getSafeNodeDataPtr(mpPmp, NodeMechanic::CharImpedance);
    mpPmp_me = getSafeNodeDataPtr(mpPmp, NodeMechanic::EquivalentMass);

    p1 = *mpP1_p; q1 = *mpP1_q; c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    p2 = *mpP2_p; q2 = *mpP2_q; c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    fmp = *mpPmp_f; xmp = *mpPmp_x; vmp = *mpPmp_v; cmp = *mpPmp_c; Zcmp = *mpPmp_Zc; eqMassmp = *mpPmp_me;
    A1 = *mp_A1;
    A2 = *mp_A2;
    SL = *mp_SL;
    Cip = *mp_Cip;
    bp = *mp_bp;
    mL = *mp_mL;
    bL = *mp_bL;
    fc = *mp_fc;
    bfc = *mp_bfc;
    xmin = *mp_xmin;
    xmax = *mp_xmax;

    double D12 = 0.0;
    delayedParts(mD11, D12, mD21);
    mD12Used = D12;
    mD12Newest = D12;
}

void HydraulicPistonMload::simulateOneTimestep()
{
    const double h = mTimestep;
    c1 = *mpP1_c; Zc1 = *mpP1_Zc;
    c2 = *mpP2_c; Zc2 = *mpP2_Zc;
    cmp = *mpPmp_c; Zcmp = *mpPmp_Zc;
    // Inputs were copied at initialisation only (reference behaviour).

    const double D11 = mD11, D12 = mD12Used, D21 = mD21;

    mX[0] = xmp; mX[1] = vmp; mX[2] = q1; mX[3] = q2; mX[4] = p1; mX[5] = p2; mX[6] = fmp;
    for (int iter = 1; iter <= 2; ++iter) {
        const double M = 2.0 * mL + h * (bL + bp + Zcmp);
        const double X = -((h * h) * (cmp + bL * vmp + bp * vmp - A1 * (c1 + q1 * Zc1) + A2 * (c2 + q2 * Zc2) + vmp * Zcmp)) / (4.0 * mL) - D11 - D12;
        const double G1 = dxLimit(X, xmin, xmax);
        // At a stroke limit the velocity is scaled down by 1e-9 (end stop, no bounce).
        const double G2 = dxLimit(limit(X, xmin, xmax), xmin, xmax);

        mF[0] = xmp - limit(X, xmin, xmax);
        mF[1] = vmp - G2 * (-(h * (cmp - A1 * (c1 + q1 * Zc1) + A2 * (c2 + q2 * Zc2))) / M - D21);
        mF[2] = Cip * (p1 - p2) + q1 + A1 * vmp;
        mF[3] = Cip * (p2 - p1) + q2 - A2 * vmp;
        mF[4] = -c1 + p1 - q1 * Zc1;
        mF[5] = -c2 + p2 - q2 * Zc2;
        mF[6] = -cmp + fmp - vmp * Zcmp;

        const double J0[7] = {1.0, (h * h) * (bL + bp + Zcmp) * G1 / (4.0 * mL), -(A1 * (h * h) * Zc1 * G1) / (4.0 * mL), A2 * (h * h) * Zc2 * G1 / (4.0 * mL), 0.0, 0.0, 0.0};
        const double J1[7] = {0.0, 1.0, -(A1 * h * Zc1 * G2) / M, A2 * h * Zc2 * G2 / M, 0.0, 0.0, 0.0};
        const double J4[7] = {0.0, 0.0, -Zc1, 0.0, 1.0, 0.0, 0.0};
        const double J5[7] = {0.0, 0.0, 0.0, -Zc2, 0.0, 1.0, 0.0};

        for (int j = 0; j < 7; ++j) {
            mJ[0][j] = J0[j];
            mJ[1][j] = J1[j];
            mJ[2][j] = 0.0;
            mJ[3][j] = 0.0;
            mJ[4][j] = J4[j];
            mJ[5][j] = J5[j];
            mJ[6][j] = 0.0;
        }
        mJ[2][1] = A1; mJ[2][2] = 1.0; mJ[2][4] = Cip; mJ[2][5] = -Cip;
        mJ[3][1] = -A2; mJ[3][3] = 1.0; mJ[3][4] = -Cip; mJ[3][5] = Cip;
        mJ[6][1] = -Zcmp; mJ[6][6] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicPistonMload: singular Jacobian");
        }
        xmp = mX[0]; vmp = mX[1]; q1 = mX[2]; q2 = mX[3]; p1 = mX[4]; p2 = mX[5]; fmp = mX[6];
    }

    // New delayed parts; D12 enters the residuals two steps later.
    double newD12 = 0.0;
    delayedParts(mD11, newD12, mD21);
    mD12Used = mD12Newest;
    mD12Newest = newD12;

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpPmp_f = fmp;
    *mpPmp_x = xmp;
    *mpPmp_v = vmp;
    *mpPmp_me = eqMassmp;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPistonMload, "Hydraulic")

} // namespace tlmhub
