#include "core/components/mechanic/MechanicVehicle1D.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

#include <cmath>

namespace tlmhub {

void MechanicVehicle1D::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("Mc", "Vehicle mass", "kg", 1000.0, &mpMc);
    addInputVariable("cfr", "Rolling resistance coefficient", "N/N", 0.02, &mpCfr);
    addInputVariable("CdA", "Effective drag area", "m2", 0.5, &mpCdA);
    addInputVariable("rwheel", "Wheel radius", "m", 1.0, &mpRwheel);
    addInputVariable("rho", "Air density", "kg/m3", 1.25, &mpRho);
    addOutputVariable("vc", "Vehicle speed", "m/s", 0.0, &mpVc);
    addOutputVariable("xc", "Vehicle position", "m", 0.0, &mpXc);
    addOutputVariable("fd", "Drag force", "N", 0.0, &mpFd);
    addOutputVariable("fr", "Rolling resistance force", "N", 0.0, &mpFr);
}

// Explicit forces from the speed of the previous step (held during the iterations).
void MechanicVehicle1D::computeForces()
{
    const double Mc = *mpMc, cfr = *mpCfr, CdA = *mpCdA, rho = *mpRho;
    mFd = (CdA * rho * mVc * std::fabs(mVc)) / 2.0;
    const double fc = 9.82 * cfr * Mc;
    const double Br = Mc / mTimestep;
    mFre = limit(Br * mVc, -fc, fc);
}

void MechanicVehicle1D::computeDelayedParts()
{
    const double dt = mTimestep;
    const double Mc = *mpMc, rw = *mpRwheel;
    mD1 = (mFd * dt * rw + mFre * dt * rw - dt * mT1 - dt * mT2 - 2.0 * Mc * rw * mVc) / (2.0 * Mc * rw);
    mD2 = (-(dt * mVc) - 2.0 * mXc) / 2.0;
    mD3 = (-2.0 * rw * mTh1 - dt * mVc) / (2.0 * rw);
}

void MechanicVehicle1D::initialize()
{
    mpT1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpA1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpW1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpC1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpZc1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpJe1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::EquivalentInertia);
    mpT2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Torque);
    mpA2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Angle);
    mpW2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::AngularVelocity);
    mpC2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::WaveVariable);
    mpZc2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::CharImpedance);
    mpJe2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::EquivalentInertia);

    mT1 = *mpT1;
    mTh1 = *mpA1;
    mW1 = *mpW1;
    mJe1 = *mpJe1;
    mT2 = *mpT2;
    mTh2 = *mpA2;
    mW2 = *mpW2;
    mJe2 = *mpJe2;
    // The output start values are the initial speed and position.
    mVc = *mpVc;
    mXc = *mpXc;
    mFr = *mpFr;

    mJac.create(5, 5);
    mF.create(5);
    mX.create(5);
    mSingularReported = false;

    computeForces();
    computeDelayedParts();
    // No step and no node writes here.
}

void MechanicVehicle1D::simulateOneTimestep()
{
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double Mc = *mpMc, rw = *mpRwheel;
    const double dt = mTimestep;

    computeForces();

    mX[0] = mVc;
    mX[1] = mXc;
    mX[2] = mTh1;
    mX[3] = mT1;
    mX[4] = mT2;

    for (int iter = 1; iter <= 2; ++iter) {
        mF[0] = mVc + (dt * (mFd * rw + mFre * rw - mT1 - mT2)) / (2.0 * Mc * rw) + mD1;
        mF[1] = mXc - (dt * mVc) / 2.0 + mD2;
        mF[2] = mTh1 - (dt * mVc) / (2.0 * rw) + mD3;
        mF[3] = -c1 + mT1 + (mVc * Zc1) / rw;
        mF[4] = -c2 + mT2 + (mVc * Zc2) / rw;

        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 5; ++j) {
                mJac[i][j] = 0.0;
            }
        }
        mJac[0][0] = 1.0;
        mJac[0][3] = -dt / (2.0 * Mc * rw);
        mJac[0][4] = -dt / (2.0 * Mc * rw);
        mJac[1][0] = -dt / 2.0;
        mJac[1][1] = 1.0;
        mJac[2][0] = -dt / (2.0 * rw);
        mJac[2][2] = 1.0;
        mJac[3][0] = Zc1 / rw;
        mJac[3][3] = 1.0;
        mJac[4][0] = Zc2 / rw;
        mJac[4][4] = 1.0;

        if (!mSolver.solve(mJac, mF, mX, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicVehicle1D: singular Jacobian");
        }
        mVc = mX[0];
        mXc = mX[1];
        mTh1 = mX[2];
        mT1 = mX[3];
        mT2 = mX[4];
        mW1 = -(mVc / rw);
        mW2 = -(mVc / rw);
        mTh2 = mTh1;
        mFr = mFre;
        mJe1 = Mc * Power(rw, 2.0);
        mJe2 = Mc * Power(rw, 2.0);
    }

    // fd and fre stay those of the start of the step.
    computeDelayedParts();

    *mpT1 = mT1;
    *mpA1 = mTh1;
    *mpW1 = mW1;
    *mpJe1 = mJe1;
    *mpT2 = mT2;
    *mpA2 = mTh2;
    *mpW2 = mW2;
    *mpJe2 = mJe2;
    *mpVc = mVc;
    *mpXc = mXc;
    *mpFd = mFd;
    *mpFr = mFr;
}

TLMHUB_REGISTER_COMPONENT(MechanicVehicle1D, "Mechanic")

} // namespace tlmhub
