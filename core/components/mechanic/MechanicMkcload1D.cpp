#include "core/components/mechanic/MechanicMkcload1D.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicMkcload1D::configure()
{
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    mpPm2 = addPowerPort("Pm2", NodeType::Mechanic);
    addInputVariable("mL", "Inertia", "kg", 1000.0, &mpML);
    addInputVariable("bL", "Viscous friction coefficient", "Ns/m", 10.0, &mpBL);
    addInputVariable("kL", "Spring constant", "N/m", 10.0, &mpKL);
    addInputVariable("fc", "Dry friction force", "N", 10.0, &mpFc);
    addInputVariable("bfc", "Numerical friction factor", "", 1.0, &mpBfc);
    addInputVariable("xmin", "Minimum position", "m", 0.0, &mpXMin);
    addInputVariable("xmax", "Maximum position", "m", 1.0, &mpXMax);
    addOutputVariable("fs", "Spring force", "N", 1000.0, &mpFs);
}

void MechanicMkcload1D::computeDelayedParts(double& p11, double& p12, double& p21) const
{
    const double dt = mTimestep;
    const double mL = *mpML, bL = *mpBL, kL = *mpKL, fc = *mpFc, bfc = *mpBfc;
    const double ffr = limit((bfc * mL * mV2) / dt, -fc, fc);
    const double K4 = 4.0 * mL + dt * (2.0 * bL + kL * dt);
    const double K2 = 2.0 * mL + bL * dt;
    p11 = (-2.0 * mF1 * Power(dt, 2.0) + 2.0 * mF2 * Power(dt, 2.0) - 8.0 * mL * mX2
           + 2.0 * kL * Power(dt, 2.0) * mX2 + 2.0 * Power(dt, 2.0) * ffr)
          / K4;
    // The bL term goes with the position here, as in the original.
    p12 = (-(mF1 * Power(dt, 2.0)) + mF2 * Power(dt, 2.0) + 4.0 * mL * mX2 - 2.0 * bL * dt * mX2
           + kL * Power(dt, 2.0) * mX2 + Power(dt, 2.0) * ffr)
          / K4;
    p21 = (-(mF1 * dt) + mF2 * dt - 2.0 * mL * mV2 + bL * dt * mV2 + kL * dt * mX2 + dt * ffr) / K2;
}

void MechanicMkcload1D::initialize()
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

    mF1 = *mpF1;
    mV1 = *mpV1;
    mMe1 = *mpMe1;
    mF2 = *mpF2;
    mX2 = *mpX2;
    mV2 = *mpV2;
    mMe2 = *mpMe2;
    mFs = *mpFs;
    mX1 = -mX2;

    mJac.create(4, 4);
    mF.create(4);
    mX.create(4);
    mSingularReported = false;

    double p11, p12, p21;
    computeDelayedParts(p11, p12, p21);
    mD11 = p11;
    mD21 = p21;
    mDelay12.initialize(9, p12);
    mD12 = mDelay12.getIdx(1);
    // No step and no node writes here.
}

void MechanicMkcload1D::simulateOneTimestep()
{
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double mL = *mpML, bL = *mpBL, kL = *mpKL, fc = *mpFc, bfc = *mpBfc;
    const double xmin = *mpXMin, xmax = *mpXMax;
    const double dt = mTimestep;
    const double K4 = 4.0 * mL + dt * (2.0 * bL + kL * dt);
    const double K2 = 2.0 * mL + bL * dt;

    mX[0] = mX2;
    mX[1] = mV2;
    mX[2] = mF1;
    mX[3] = mF2;

    for (int iter = 1; iter <= 2; ++iter) {
        const double ffr = limit((bfc * mL * mV2) / dt, -fc, fc);
        const double q = dxLimit((bfc * mL * mV2) / dt, -fc, fc);
        const double A = -(Power(dt, 2.0) * (-mF1 + mF2 + ffr)) / K4 - mD11 - mD12;
        const double Al = limit(A, xmin, xmax);
        const double g = dxLimit(Al, xmin, xmax);
        const double h = dxLimit(A, xmin, xmax);

        mF[0] = mX2 - Al;
        mF[1] = mV2 - g * (-((dt * (-mF1 + mF2 + kL * mX2 + ffr)) / K2) - mD21);
        mF[2] = -c1 + mF1 + mV2 * Zc1;
        mF[3] = -c2 + mF2 - mV2 * Zc2;

        mJac[0][0] = 1.0;
        mJac[0][1] = (bfc * mL * dt * q * h) / K4;
        mJac[0][2] = -(Power(dt, 2.0) * h) / K4;
        mJac[0][3] = (Power(dt, 2.0) * h) / K4;
        mJac[1][0] = (kL * dt * g) / K2;
        mJac[1][1] = 1.0 + (bfc * mL * q * g) / K2;
        mJac[1][2] = -(dt * g) / K2;
        mJac[1][3] = (dt * g) / K2;
        mJac[2][0] = 0.0;
        mJac[2][1] = Zc1;
        mJac[2][2] = 1.0;
        mJac[2][3] = 0.0;
        mJac[3][0] = 0.0;
        mJac[3][1] = -Zc2;
        mJac[3][2] = 0.0;
        mJac[3][3] = 1.0;

        if (!mSolver.solve(mJac, mF, mX, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicMkcload1D: singular Jacobian");
        }
        mX2 = mX[0];
        mV2 = mX[1];
        mF1 = mX[2];
        mF2 = mX[3];
        mV1 = -mV2;
        mX1 = -mX2;
        mFs = kL * mX2;
        mMe1 = mL;
        mMe2 = mL;
    }

    double p11, p12, p21;
    computeDelayedParts(p11, p12, p21);
    mD11 = p11;
    mD21 = p21;
    mD12 = mDelay12.getIdx(0);
    mDelay12.update(p12);

    *mpF1 = mF1;
    *mpX1 = mX1;
    *mpV1 = mV1;
    *mpMe1 = mMe1;
    *mpF2 = mF2;
    *mpX2 = mX2;
    *mpV2 = mV2;
    *mpMe2 = mMe2;
    *mpFs = mFs;
}

TLMHUB_REGISTER_COMPONENT(MechanicMkcload1D, "Mechanic")

} // namespace tlmhub
