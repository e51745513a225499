#include "core/components/mechanic/MechanicJLink.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicJLink::configure()
{
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("JL", "Inertia at node 2", "kg m^2", 1.0, &mpJL);
    addInputVariable("BL", "Viscous friction at node 2", "Nm s/rad", 1.0, &mpBL);
    addInputVariable("link", "Link length", "m", 0.1, &mpLink);
    addInputVariable("x0", "Position of Pm1 at zero angle", "m", -0.1, &mpX0);
    addInputVariable("theta0", "Initial angle (unused)", "rad", 0.1, &mpTheta0);
    addInputVariable("thetamin", "Minimum angle", "rad", -1.05, &mpThetaMin);
    addInputVariable("thetamax", "Maximum angle", "rad", 1.05, &mpThetaMax);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"theta0"}, false);
}

void MechanicJLink::computeDelayedParts(double& p11, double& p21, double& p22) const
{
    const double dt = mTimestep;
    const double JL = *mpJL, BL = *mpBL, L = *mpLink;
    p11 = (dt * mT2 - 2.0 * JL * mW2 + BL * dt * mW2 - mF1 * L * dt * Cos(mTh2)) / (2.0 * JL + BL * dt);
    p21 = (-8.0 * JL * mTh2 + 2.0 * Power(dt, 2.0) * mT2 + 2.0 * BL * Power(dt, 2.0) * mW2
           - 2.0 * mF1 * L * Power(dt, 2.0) * Cos(mTh2))
          / (4.0 * JL);
    p22 = (4.0 * JL * mTh2 + Power(dt, 2.0) * mT2 + BL * Power(dt, 2.0) * mW2
           - mF1 * L * Power(dt, 2.0) * Cos(mTh2))
          / (4.0 * JL);
}

void MechanicJLink::initialize()
{
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

    mF1 = *mpF1;
    mX1 = *mpX1;
    mV1 = *mpV1;
    mMe1 = *mpMe1;
    mT2 = *mpT2;
    mTh2 = *mpA2;
    mW2 = *mpW2;
    mJe2 = *mpJe2;

    mJac.create(4, 4);
    mF.create(4);
    mX.create(4);
    mSingularReported = false;

    double p11, p21, p22;
    computeDelayedParts(p11, p21, p22);
    mD11 = p11;
    mD21 = p21;
    // Second-order delayed part: a buffer filled with the initial value.
    mDelay22.initialize(9, p22);
    mD22 = mDelay22.getIdx(1);

    // The original advances one step already here.
    simulateOneTimestep();
}

void MechanicJLink::simulateOneTimestep()
{
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double JL = *mpJL, BL = *mpBL, L = *mpLink, x0 = *mpX0;
    const double thmin = *mpThetaMin, thmax = *mpThetaMax;
    const double dt = mTimestep;
    const double K1 = 2.0 * JL + BL * dt;
    const double K2 = 4.0 * JL;

    mX[0] = mW2;
    mX[1] = mTh2;
    mX[2] = mF1;
    mX[3] = mT2;

    for (int iter = 1; iter <= 2; ++iter) {
        const double A = -(Power(dt, 2.0) * (mT2 + BL * mW2 - mF1 * L * Cos(mTh2))) / K2 - mD21 - mD22;
        const double Al = limit(A, thmin, thmax);
        const double g = dxLimit(Al, thmin, thmax);
        const double h = dxLimit(A, thmin, thmax);

        mF[0] = mW2 - g * (-((dt * (mT2 - mF1 * L * Cos(mTh2))) / K1) - mD11);
        mF[1] = mTh2 - Al;
        mF[2] = -c1 + mF1 + L * mW2 * Zc1 * Cos(mTh2);
        mF[3] = -c2 + mT2 - mW2 * Zc2;

        mJac[0][0] = 1.0;
        mJac[0][1] = (mF1 * L * dt * g * Sin(mTh2)) / K1;
        mJac[0][2] = -((L * dt * Cos(mTh2) * g) / K1);
        mJac[0][3] = (dt * g) / K1;
        mJac[1][0] = (BL * Power(dt, 2.0) * h) / K2;
        mJac[1][1] = 1.0 + (mF1 * L * Power(dt, 2.0) * h * Sin(mTh2)) / K2;
        mJac[1][2] = -(L * Power(dt, 2.0) * Cos(mTh2) * h) / K2;
        mJac[1][3] = (Power(dt, 2.0) * h) / K2;
        mJac[2][0] = L * Zc1 * Cos(mTh2);
        mJac[2][1] = -(L * mW2 * Zc1 * Sin(mTh2));
        mJac[2][2] = 1.0;
        mJac[2][3] = 0.0;
        mJac[3][0] = -Zc2;
        mJac[3][1] = 0.0;
        mJac[3][2] = 0.0;
        mJac[3][3] = 1.0;

        if (!mSolver.solve(mJac, mF, mX, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicJLink: singular Jacobian");
        }
        mW2 = mX[0];
        mTh2 = mX[1];
        mF1 = mX[2];
        mT2 = mX[3];
        mV1 = -(L * mW2 * Cos(mTh2));
        mX1 = x0 - L * Sin(mTh2);
        mMe1 = (JL * Power(Sec(mTh2), 2.0)) / Power(L, 2.0);
        mJe2 = JL;
    }

    double p11, p21, p22;
    computeDelayedParts(p11, p21, p22);
    mD11 = p11;
    mD21 = p21;
    // Read before pushing: the part used next step is two evaluations old.
    mD22 = mDelay22.getIdx(0);
    mDelay22.update(p22);

    *mpF1 = mF1;
    *mpX1 = mX1;
    *mpV1 = mV1;
    *mpMe1 = mMe1;
    *mpT2 = mT2;
    *mpA2 = mTh2;
    *mpW2 = mW2;
    *mpJe2 = mJe2;
}

TLMHUB_REGISTER_COMPONENT(MechanicJLink, "Mechanic")

} // namespace tlmhub
