#include "core/components/mechanic/MechanicJLink2.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicJLink2::configure()
{
    mpPm0 = addPowerPort("Pm0", NodeType::Mechanic);
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("JL", "Inertia at node 2", "kg m^2", 1.0, &mpJL);
    addInputVariable("BL", "Viscous friction at node 2", "Nm s/rad", 1.0, &mpBL);
    addInputVariable("link", "Link length", "m", 0.1, &mpLink);
    addInputVariable("x0", "Position of the translational ports at zero angle", "m", -0.1, &mpX0);
    addInputVariable("thetamin", "Minimum angle", "rad", -1.05, &mpThetaMin);
    addInputVariable("thetamax", "Maximum angle", "rad", 1.05, &mpThetaMax);
}

void MechanicJLink2::computeDelayedParts(double& p11, double& p21, double& p22) const
{
    const double dt = mTimestep;
    const double JL = *mpJL, BL = *mpBL, L = *mpLink;
    const double fs = mF0 + mF1;
    p11 = (dt * mT2 - 2.0 * JL * mW2 + BL * dt * mW2 - fs * L * dt * Cos(mTh2)) / (2.0 * JL + BL * dt);
    p21 = (-8.0 * JL * mTh2 + 2.0 * Power(dt, 2.0) * mT2 + 2.0 * BL * Power(dt, 2.0) * mW2
           - 2.0 * fs * L * Power(dt, 2.0) * Cos(mTh2))
          / (4.0 * JL);
    p22 = (4.0 * JL * mTh2 + Power(dt, 2.0) * mT2 + BL * Power(dt, 2.0) * mW2
           - fs * L * Power(dt, 2.0) * Cos(mTh2))
          / (4.0 * JL);
}

void MechanicJLink2::initialize()
{
    mpF0 = getSafeNodeDataPtr(mpPm0, NodeMechanic::Force);
    mpX0port = getSafeNodeDataPtr(mpPm0, NodeMechanic::Position);
    mpV0 = getSafeNodeDataPtr(mpPm0, NodeMechanic::Velocity);
    mpC0 = getSafeNodeDataPtr(mpPm0, NodeMechanic::WaveVariable);
    mpZc0 = getSafeNodeDataPtr(mpPm0, NodeMechanic::CharImpedance);
    mpMe0 = getSafeNodeDataPtr(mpPm0, NodeMechanic::EquivalentMass);
    mpF1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Force);
    mpX1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Position);
    mpV1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpC1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpZc1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::CharImpedance);
    mpMe1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::EquivalentMass);
    mpT2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Torque);
    mpA2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Angle);
    mpW2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::AngularVelocity);
    mpC2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::WaveVariable);
    mpZc2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::CharImpedance);
    mpJe2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::EquivalentInertia);

    mF0 = *mpF0;
    mXp0 = *mpX0port;
    mVp0 = *mpV0;
    mMe0 = *mpMe0;
    mF1 = *mpF1;
    mX1 = *mpX1;
    mV1 = *mpV1;
    mMe1 = *mpMe1;
    mT2 = *mpT2;
    mTh2 = *mpA2;
    mW2 = *mpW2;
    mJe2 = *mpJe2;

    mJac.create(5, 5);
    mF.create(5);
    mX.create(5);
    mSingularReported = false;

    double p11, p21, p22;
    computeDelayedParts(p11, p21, p22);
    mD11 = p11;
    mD21 = p21;
    mDelay22.initialize(9, p22);
    mD22 = mDelay22.getIdx(1);

    // The original advances one step already here.
    simulateOneTimestep();
}

void MechanicJLink2::simulateOneTimestep()
{
    const double c0 = *mpC0, Zc0 = *mpZc0;
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double JL = *mpJL, BL = *mpBL, L = *mpLink, x0 = *mpX0;
    const double thmin = *mpThetaMin, thmax = *mpThetaMax;
    const double dt = mTimestep;
    const double K1 = 2.0 * JL + BL * dt;
    const double K2 = 4.0 * JL;

    mX[0] = mW2;
    mX[1] = mTh2;
    mX[2] = mF0;
    mX[3] = mF1;
    mX[4] = mT2;

    for (int iter = 1; iter <= 2; ++iter) {
        const double fs = mF0 + mF1;
        const double A = -(Power(dt, 2.0) * (mT2 + BL * mW2 - fs * L * Cos(mTh2))) / K2 - mD21 - mD22;
        const double Al = limit(A, thmin, thmax);
        const double g = dxLimit(Al, thmin, thmax);
        const double h = dxLimit(A, thmin, thmax);

        mF[0] = mW2 - g * (-((dt * (mT2 - fs * L * Cos(mTh2))) / K1) - mD11);
        mF[1] = mTh2 - Al;
        mF[2] = -c0 + mF0 + L * mW2 * Zc0 * Cos(mTh2);
        mF[3] = -c1 + mF1 + L * mW2 * Zc1 * Cos(mTh2);
        mF[4] = -c2 + mT2 - mW2 * Zc2;

        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 5; ++j) {
                mJac[i][j] = 0.0;
            }
        }
        mJac[0][0] = 1.0;
        mJac[0][1] = (fs * L * dt * g * Sin(mTh2)) / K1;
        mJac[0][2] = -((L * dt * Cos(mTh2) * g) / K1);
        mJac[0][3] = -((L * dt * Cos(mTh2) * g) / K1);
        mJac[0][4] = (dt * g) / K1;
        mJac[1][0] = (BL * Power(dt, 2.0) * h) / K2;
        mJac[1][1] = 1.0 + (fs * L * Power(dt, 2.0) * h * Sin(mTh2)) / K2;
        mJac[1][2] = -(L * Power(dt, 2.0) * Cos(mTh2) * h) / K2;
        mJac[1][3] = -(L * Power(dt, 2.0) * Cos(mTh2) * h) / K2;
        mJac[1][4] = (Power(dt, 2.0) * h) / K2;
        mJac[2][0] = L * Zc0 * Cos(mTh2);
        mJac[2][1] = -(L * mW2 * Zc0 * Sin(mTh2));
        mJac[2][2] = 1.0;
        mJac[3][0] = L * Zc1 * Cos(mTh2);
        mJac[3][1] = -(L * mW2 * Zc1 * Sin(mTh2));
        mJac[3][3] = 1.0;
        mJac[4][0] = -Zc2;
        mJac[4][4] = 1.0;

        if (!mSolver.solve(mJac, mF, mX, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicJLink2: singular Jacobian");
        }
        mW2 = mX[0];
        mTh2 = mX[1];
        mF0 = mX[2];
        mF1 = mX[3];
        mT2 = mX[4];
        mV1 = -(L * mW2 * Cos(mTh2));
        mVp0 = mV1;
        mX1 = x0 - L * Sin(mTh2);
        mXp0 = mX1;
        mMe1 = (JL * Power(Sec(mTh2), 2.0)) / Power(L, 2.0);
        mMe0 = mMe1;
        mJe2 = JL;
    }

    double p11, p21, p22;
    computeDelayedParts(p11, p21, p22);
    mD11 = p11;
    mD21 = p21;
    mD22 = mDelay22.getIdx(0);
    mDelay22.update(p22);

    *mpF0 = mF0;
    *mpX0port = mXp0;
    *mpV0 = mVp0;
    *mpMe0 = mMe0;
    *mpF1 = mF1;
    *mpX1 = mX1;
    *mpV1 = mV1;
    *mpMe1 = mMe1;
    *mpT2 = mT2;
    *mpA2 = mTh2;
    *mpW2 = mW2;
    *mpJe2 = mJe2;
}

TLMHUB_REGISTER_COMPONENT(MechanicJLink2, "Mechanic")

} // namespace tlmhub
