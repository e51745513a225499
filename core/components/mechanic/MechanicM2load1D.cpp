#include "core/components/mechanic/MechanicM2load1D.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicM2load1D::configure()
{
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    mpPm2 = addPowerPort("Pm2", NodeType::Mechanic);
    mpPm3 = addPowerPort("Pm3", NodeType::Mechanic);
    addInputVariable("m1", "Mass 1", "kg", 1000.0, &mpM1);
    addInputVariable("m2", "Mass 2", "kg", 1000.0, &mpM2);
    addInputVariable("bL", "Viscous friction coefficient (unused)", "Ns/m", 10.0, &mpBL);
    addInputVariable("fc", "Dry friction force", "N", 10.0, &mpFc);
    addInputVariable("bfc", "Numerical friction factor", "", 1.0, &mpBfc);
    addInputVariable("xpmin", "Minimum stroke", "m", 0.0, &mpXpMin);
    addInputVariable("xpmax", "Maximum stroke", "m", 1.0, &mpXpMax);
    addOutputVariable("vt", "Centre of gravity speed", "m/s", 0.0, &mpVt);
    addOutputVariable("xt", "Centre of gravity position", "m", 0.0, &mpXt);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"bL"}, false);
}

void MechanicM2load1D::computeDelayedParts()
{
    const double dt = mTimestep;
    const double m1 = *mpM1, m2 = *mpM2, fc = *mpFc, bfc = *mpBfc;
    const double M = m1 + m2;
    const double ffr = limit((2.0 * bfc * m1 * m2 * mV3) / (M * dt), -fc, fc);
    const double S = -(mF2 * m1) + mF3 * m1 - mF1 * m2 + mF3 * m2 + M * ffr;
    mP31 = (dt * S - 2.0 * m1 * m2 * mV3) / (2.0 * m1 * m2);
    mP41 = (2.0 * Power(dt, 2.0) * S - 8.0 * m1 * m2 * mX3) / (4.0 * m1 * m2);
    mP42 = (Power(dt, 2.0) * S + 4.0 * m1 * m2 * mX3) / (4.0 * m1 * m2);
    mP51 = (-(mF1 * dt) + mF2 * dt - 2.0 * M * mVt) / (2.0 * M);
    mP61 = (-(dt * mVt) - 2.0 * mXt) / 2.0;
}

void MechanicM2load1D::initialize()
{
    mpF1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Force);
    mpX1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Position);
    mpV1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpC1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpZc1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::CharImpedance);
    mpMe1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::EquivalentMass);
    mpF2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::Force);
    mpX2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::Position);
    mpV2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::Velocity);
    mpC2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::WaveVariable);
    mpZc2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::CharImpedance);
    mpMe2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::EquivalentMass);
    mpF3 = getSafeNodeDataPtr(mpPm3, NodeMechanic::Force);
    mpX3 = getSafeNodeDataPtr(mpPm3, NodeMechanic::Position);
    mpV3 = getSafeNodeDataPtr(mpPm3, NodeMechanic::Velocity);
    mpC3 = getSafeNodeDataPtr(mpPm3, NodeMechanic::WaveVariable);
    mpZc3 = getSafeNodeDataPtr(mpPm3, NodeMechanic::CharImpedance);
    mpMe3 = getSafeNodeDataPtr(mpPm3, NodeMechanic::EquivalentMass);

    mF1 = *mpF1;
    mV1 = *mpV1;
    mMe1 = *mpMe1;
    mF2 = *mpF2;
    mX2 = *mpX2;
    mV2 = *mpV2;
    mMe2 = *mpMe2;
    mF3 = *mpF3;
    mX3 = *mpX3;
    mV3 = *mpV3;
    // EquivalentMass of Pm3 keeps its start value for the whole run.
    mMe3 = *mpMe3;
    mVt = *mpVt;
    mXt = *mpXt;
    mX1 = -mX2;

    mJac.create(9, 9);
    mF.create(9);
    mX.create(9);
    mSingularReported = false;

    computeDelayedParts();
    mD31 = mP31;
    mD41 = mP41;
    mD51 = mP51;
    mD61 = mP61;
    mDelay42.initialize(9, mP42);
    mD42 = mDelay42.getIdx(1);

    // The original advances one step already here.
    simulateOneTimestep();
}

void MechanicM2load1D::simulateOneTimestep()
{
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double c3 = *mpC3, Zc3 = *mpZc3;
    const double m1 = *mpM1, m2 = *mpM2, fc = *mpFc, bfc = *mpBfc;
    const double xpmin = *mpXpMin, xpmax = *mpXpMax;
    const double dt = mTimestep;
    const double M = m1 + m2;

    mX[0] = mV1;
    mX[1] = mV2;
    mX[2] = mV3;
    mX[3] = mX3;
    mX[4] = mVt;
    mX[5] = mXt;
    mX[6] = mF1;
    mX[7] = mF2;
    mX[8] = mF3;

    for (int iter = 1; iter <= 2; ++iter) {
        const double fArg = (2.0 * bfc * m1 * m2 * mV3) / (M * dt);
        const double ffr = limit(fArg, -fc, fc);
        const double q = dxLimit(fArg, -fc, fc);
        const double S = -(mF2 * m1) + mF3 * m1 - mF1 * m2 + mF3 * m2 + M * ffr;
        const double A = -(Power(dt, 2.0) * S) / (4.0 * m1 * m2) - mD41 - mD42;
        const double Al = limit(A, -xpmax, -xpmin);
        const double g = dxLimit(Al, -xpmax, -xpmin);
        const double h = dxLimit(A, -xpmax, -xpmin);

        mF[0] = mV1 + (m1 * mVt + m2 * (mV3 + mVt)) / M;
        mF[1] = mV2 + (m1 * mV3 - m1 * mVt - m2 * mVt) / M;
        mF[2] = mV3 - g * (-((dt * S) / (2.0 * m1 * m2)) - mD31);
        mF[3] = mX3 - Al;
        mF[4] = ((mF2 - mF1) * dt) / (2.0 * M) + mVt + mD51;
        mF[5] = -(dt * mVt) / 2.0 + mXt + mD61;
        // Uses v2 (not v1) for port 1, as in the original.
        mF[6] = -c1 + mF1 + mV2 * Zc1;
        mF[7] = -c2 + mF2 - mV2 * Zc2;
        mF[8] = -c3 + mF3 - mV3 * Zc3;

        for (int i = 0; i < 9; ++i) {
            for (int j = 0; j < 9; ++j) {
                mJac[i][j] = 0.0;
            }
        }
        mJac[0][0] = 1.0;
        mJac[0][2] = m2 / M;
        mJac[0][4] = 1.0;
        mJac[1][1] = 1.0;
        mJac[1][2] = m1 / M;
        mJac[1][4] = -1.0;
        mJac[2][2] = 1.0 + bfc * q * g;
        mJac[2][6] = -(dt * g) / (2.0 * m1);
        mJac[2][7] = -(dt * g) / (2.0 * m2);
        mJac[2][8] = (M * dt * g) / (2.0 * m1 * m2);
        mJac[3][2] = (bfc * dt * q * h) / 2.0;
        mJac[3][3] = 1.0;
        mJac[3][6] = -(Power(dt, 2.0) * h) / (4.0 * m1);
        mJac[3][7] = -(Power(dt, 2.0) * h) / (4.0 * m2);
        mJac[3][8] = (M * Power(dt, 2.0) * h) / (4.0 * m1 * m2);
        mJac[4][4] = 1.0;
        mJac[4][6] = -dt / (2.0 * M);
        mJac[4][7] = dt / (2.0 * M);
        mJac[5][4] = -dt / 2.0;
        mJac[5][5] = 1.0;
        mJac[6][1] = Zc1;
        mJac[6][6] = 1.0;
        mJac[7][1] = -Zc2;
        mJac[7][7] = 1.0;
        mJac[8][2] = -Zc3;
        mJac[8][8] = 1.0;

        if (!mSolver.solve(mJac, mF, mX, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicM2load1D: singular Jacobian");
        }
        mV1 = mX[0];
        mV2 = mX[1];
        mV3 = mX[2];
        mX3 = mX[3];
        mVt = mX[4];
        mXt = mX[5];
        mF1 = mX[6];
        mF2 = mX[7];
        mF3 = mX[8];
        mX1 = -(m2 * mX3 + M * mXt) / M;
        mX2 = -(m1 * mX3 - M * mXt) / M;
        mMe1 = m1;
        mMe2 = m2;
    }

    computeDelayedParts();
    mD31 = mP31;
    mD41 = mP41;
    mD51 = mP51;
    mD61 = mP61;
    mD42 = mDelay42.getIdx(0);
    mDelay42.update(mP42);

    *mpF1 = mF1;
    *mpX1 = mX1;
    *mpV1 = mV1;
    *mpMe1 = mMe1;
    *mpF2 = mF2;
    *mpX2 = mX2;
    *mpV2 = mV2;
    *mpMe2 = mMe2;
    *mpF3 = mF3;
    *mpX3 = mX3;
    *mpV3 = mV3;
    *mpMe3 = mMe3;
    *mpVt = mVt;
    *mpXt = mXt;
}

TLMHUB_REGISTER_COMPONENT(MechanicM2load1D, "Mechanic")

} // namespace tlmhub
