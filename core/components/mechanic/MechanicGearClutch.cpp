#include "core/components/mechanic/MechanicGearClutch.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicGearClutch::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("gearRatio", "Gear ratio wmr1/wmr2", "", 1.0, &mpGearRatio);
    addInputVariable("tmax", "Maximum transmitted torque at port 1", "Nm", 500.0, &mpTmax);
    addInputVariable("Jg", "Inertia at port 2", "kg", 1.0, &mpJg);
    addInputVariable("Bg", "Viscous friction at port 2", "", 0.0, &mpBg);
    addInputVariable("myfric", "Gear friction coefficient (unused)", "", 0.01, &mpMyfric);
    addInputVariable("wc", "Clutch speed (unused)", "rad/s", 1.0, &mpWc);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Jg", "Bg", "myfric", "wc"}, false);
}

void MechanicGearClutch::computeDelayedParts()
{
    const double n = *mpGearRatio;
    const double dt = mTimestep;
    mD1 = (-(n * dt * mT1) - dt * mT2 - 2.0 * mJg * mW2 + mBg * dt * mW2) / (2.0 * mJg + mBg * dt);
    mD2 = (-2.0 * mTh2 - dt * mW2) / 2.0;
    mD3 = (-2.0 * mTh1 + n * dt * mW2) / 2.0;
}

void MechanicGearClutch::initialize()
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

    mJg = *mpJg;
    mBg = *mpBg;

    mJac.create(6, 6);
    mF.create(6);
    mX.create(6);
    mSingularReported = false;

    computeDelayedParts();
}

void MechanicGearClutch::simulateOneTimestep()
{
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double n = *mpGearRatio;
    const double tmax = *mpTmax;
    const double dt = mTimestep;
    const double K = 2.0 * mJg + mBg * dt;

    mX[0] = mW2;
    mX[1] = mTh2;
    mX[2] = mTh1;
    mX[3] = mT1;
    mX[4] = mW1;
    mX[5] = mT2;

    for (int iter = 1; iter <= 2; ++iter) {
        mF[0] = -((dt * (n * mT1 + mT2)) / K) + mW2 + mD1;
        mF[1] = mTh2 - (dt * mW2) / 2.0 + mD2;
        mF[2] = mTh1 + (n * dt * mW2) / 2.0 + mD3;
        mF[3] = mT1 - limit(c1 - n * mW2 * Zc1, -tmax, tmax);
        mF[4] = mW1 + (c1 - mT1) / Zc1;
        mF[5] = -c2 + mT2 - mW2 * Zc2;

        for (int i = 0; i < 6; ++i) {
            for (int j = 0; j < 6; ++j) {
                mJac[i][j] = 0.0;
            }
        }
        mJac[0][0] = 1.0;
        mJac[0][3] = -((n * dt) / K);
        mJac[0][5] = -(dt / K);
        mJac[1][0] = -dt / 2.0;
        mJac[1][1] = 1.0;
        mJac[2][0] = (n * dt) / 2.0;
        mJac[2][2] = 1.0;
        mJac[3][0] = n * Zc1 * dxLimit(c1 - n * mW2 * Zc1, -tmax, tmax);
        mJac[3][3] = 1.0;
        mJac[4][3] = -(1.0 / Zc1);
        mJac[4][4] = 1.0;
        mJac[5][0] = -Zc2;
        mJac[5][5] = 1.0;

        if (!mSolver.solve(mJac, mF, mX, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicGearClutch: singular Jacobian");
        }
        mW2 = mX[0];
        mTh2 = mX[1];
        mTh1 = mX[2];
        mT1 = mX[3];
        mW1 = mX[4];
        mT2 = mX[5];
        mJe1 = mJg / Power(n, 2.0);
        mJe2 = mJg;
    }

    computeDelayedParts();

    *mpT1 = mT1;
    *mpA1 = mTh1;
    *mpW1 = mW1;
    *mpJe1 = mJe1;
    *mpT2 = mT2;
    *mpA2 = mTh2;
    *mpW2 = mW2;
    *mpJe2 = mJe2;
}

TLMHUB_REGISTER_COMPONENT(MechanicGearClutch, "Mechanic")

} // namespace tlmhub
