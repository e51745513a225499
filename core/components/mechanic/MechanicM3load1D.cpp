#include "core/components/mechanic/MechanicM3load1D.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void MechanicM3load1D::configure()
{
    mpPm[0] = addPowerPort("Pm1", NodeType::Mechanic);
    mpPm[1] = addPowerPort("Pm2", NodeType::Mechanic);
    mpPm[2] = addPowerPort("Pm3", NodeType::Mechanic);

    addInputVariable("m1FrictionCoulomb", "Dry friction between M1 and ground (+/-)", "N", 10.0, &mpFc[0]);
    addInputVariable("m2FrictionCoulomb", "Dry friction between M2 and ground (+/-)", "N", 10.0, &mpFc[1]);
    addInputVariable("m3FrictionCoulomb", "Dry friction between M3 and ground (+/-)", "N", 10.0, &mpFc[2]);
    addInputVariable("m12FrictionCoulomb", "Dry friction between M1 and M2 (+/-)", "N", 10.0, &mpFc12);
    addInputVariable("m13FrictionCoulomb", "Dry friction between M1 and M3 (+/-)", "N", 10.0, &mpFc13);

    addInputVariable("m1Mass", "Mass of M1", "kg", 10.0, &mpMass[0]);
    addInputVariable("m2Mass", "Mass of M2", "kg", 1.0, &mpMass[1]);
    addInputVariable("m3Mass", "Mass of M3", "kg", 1.0, &mpMass[2]);
    addInputVariable("m1FrictionViscousCoeff", "Viscous friction between M1 and ground", "Ns/m", 10.0, &mpB[0]);
    addInputVariable("m2FrictionViscousCoeff", "Viscous friction between M2 and ground", "Ns/m", 10.0, &mpB[1]);
    addInputVariable("m3FrictionViscousCoeff", "Viscous friction between M3 and ground", "Ns/m", 10.0, &mpB[2]);
    addInputVariable("m12FrictionViscousCoeff", "Viscous friction between M1 and M2", "Ns/m", 10.0, &mpB12);
    addInputVariable("m13FrictionViscousCoeff", "Viscous friction between M1 and M3", "Ns/m", 10.0, &mpB13);
    addInputVariable("bfc", "Numerical friction factor", "", 1.0, &mpBfc);
    addInputVariable("m1PositionLimitNeg", "Lower stroke limit of Pm1's position", "m", -1000.0, &mpXMin[0]);
    addInputVariable("m1PositionLimitPos", "Upper stroke limit of Pm1's position", "m", 1000.0, &mpXMax[0]);
    addInputVariable("m1PositionOffset", "Offset of the position output of M1", "m", 0.0, &mpOffset[0]);
    addInputVariable("m1Direction", "Direction (1 or -1) of the outputs of M1", "", 1.0, &mpDir[0]);
    addInputVariable("m2PositionLimitNeg", "Lower stroke limit of Pm2's position", "m", -1000.0, &mpXMin[1]);
    addInputVariable("m2PositionLimitPos", "Upper stroke limit of Pm2's position", "m", 1000.0, &mpXMax[1]);
    addInputVariable("m2PositionOffset", "Offset of the position output of M2", "m", 0.0, &mpOffset[1]);
    addInputVariable("m2Direction", "Direction (1 or -1) of the outputs of M2", "", 1.0, &mpDir[1]);
    addInputVariable("m3PositionLimitNeg", "Lower stroke limit of Pm3's position", "m", -1000.0, &mpXMin[2]);
    addInputVariable("m3PositionLimitPos", "Upper stroke limit of Pm3's position", "m", 1000.0, &mpXMax[2]);
    addInputVariable("m3PositionOffset", "Offset of the position output of M3", "m", 0.0, &mpOffset[2]);
    addInputVariable("m3Direction", "Direction (1 or -1) of the outputs of M3", "", 1.0, &mpDir[2]);

    addOutputVariable("m1Position", "Position of M1", "m", 0.0, &mpPosOut[0]);
    addOutputVariable("m2Position", "Position of M2", "m", 0.0, &mpPosOut[1]);
    addOutputVariable("m3Position", "Position of M3", "m", 0.0, &mpPosOut[2]);
    addOutputVariable("m1Velocity", "Velocity of M1", "m/s", 0.0, &mpVelOut[0]);
    addOutputVariable("m2Velocity", "Velocity of M2", "m/s", 0.0, &mpVelOut[1]);
    addOutputVariable("m3Velocity", "Velocity of M3", "m/s", 0.0, &mpVelOut[2]);
    addOutputVariable("m1FrictionForce", "Friction force between M1 and ground", "N", 0.0, &mpFricOut[0]);
    addOutputVariable("m2FrictionForce", "Friction force between M2 and ground", "N", 0.0, &mpFricOut[1]);
    addOutputVariable("m3FrictionForce", "Friction force between M3 and ground", "N", 0.0, &mpFricOut[2]);
    addOutputVariable("m12FrictionForce", "Friction force between M1 and M2", "N", 0.0, &mpFric12Out);
    addOutputVariable("m13FrictionForce", "Friction force between M1 and M3", "N", 0.0, &mpFric13Out);
}

MechanicM3load1D::Inputs MechanicM3load1D::readInputs() const
{
    Inputs in{};
    for (int k = 0; k < 3; ++k) {
        in.m[k] = *mpMass[k];
        in.b[k] = *mpB[k];
        in.fc[k] = *mpFc[k];
        in.xMin[k] = *mpXMin[k];
        in.xMax[k] = *mpXMax[k];
        in.offset[k] = *mpOffset[k];
        in.dir[k] = *mpDir[k];
    }
    in.b12 = *mpB12;
    in.b13 = *mpB13;
    in.fc12 = *mpFc12;
    in.fc13 = *mpFc13;
    in.bfc = *mpBfc;
    return in;
}

// Dry friction is the "numerical friction" of Hopsan's generated loads: the force that would
// stop the relative motion within one step (scaled by bfc), clamped to +-fc.
MechanicM3load1D::Loads MechanicM3load1D::loads(const Inputs& in) const
{
    const double dt = mTimestep;
    const double bfc = in.bfc;
    const double m1 = in.m[0], m2 = in.m[1], m3 = in.m[2];
    const double v1 = mV[0], v2 = mV[1], v3 = mV[2];
    Loads l{};

    double dfr[3];
    for (int k = 0; k < 3; ++k) {
        const double arg = (-2.0 * bfc * in.m[k] * mV[k]) / dt;
        l.fr[k] = limit(arg, -in.fc[k], in.fc[k]);
        dfr[k] = dxLimit(arg, -in.fc[k], in.fc[k]) * (-2.0 * bfc * in.m[k]) / dt;
    }
    const double arg12 = (-2.0 * bfc * m1 * m2 * (v1 - v2)) / ((m1 + m2) * dt);
    const double arg13 = (-2.0 * bfc * m1 * m3 * (v1 - v3)) / ((m1 + m3) * dt);
    l.fr12 = limit(arg12, -in.fc12, in.fc12);
    l.fr13 = limit(arg13, -in.fc13, in.fc13);
    // Derivatives of fr12 (fr13) with respect to v1; with respect to v2 (v3) they change sign.
    const double d12 = dxLimit(arg12, -in.fc12, in.fc12) * (-2.0 * bfc * m1 * m2) / ((m1 + m2) * dt);
    const double d13 = dxLimit(arg13, -in.fc13, in.fc13) * (-2.0 * bfc * m1 * m3) / ((m1 + m3) * dt);

    // m1 dv1/dt = g1 - (b1 + b12 + b13) v1, m2 dv2/dt = g2 - (b2 + b12) v2, likewise M3.
    l.g[0] = -mF[0] + in.b12 * v2 + in.b13 * v3 + l.fr[0] + l.fr12 + l.fr13;
    l.g[1] = -mF[1] + in.b12 * v1 + l.fr[1] - l.fr12;
    l.g[2] = -mF[2] + in.b13 * v1 + l.fr[2] - l.fr13;

    l.dg[0][0] = dfr[0] + d12 + d13;
    l.dg[0][1] = in.b12 - d12;
    l.dg[0][2] = in.b13 - d13;
    l.dg[1][0] = in.b12 - d12;
    l.dg[1][1] = dfr[1] + d12;
    l.dg[1][2] = 0.0;
    l.dg[2][0] = in.b13 - d13;
    l.dg[2][1] = 0.0;
    l.dg[2][2] = dfr[2] + d13;
    return l;
}

// Trapezoidal rule, m dv/dt = g - B v over one step:
//   (2m + B dt) v[n] = dt g[n] + (2m - B dt) v[n-1] + dt g[n-1],
// so v[n] = dt g[n] / (2m + B dt) - Dv with Dv from step n-1; and x[n] = dt v[n] / 2 - Dx.
void MechanicM3load1D::computeDelayedParts(const Inputs& in, const Loads& l)
{
    const double dt = mTimestep;
    const double bSum[3] = {in.b[0] + in.b12 + in.b13, in.b[1] + in.b12, in.b[2] + in.b13};
    for (int k = 0; k < 3; ++k) {
        mDv[k] = (-dt * l.g[k] + (bSum[k] * dt - 2.0 * in.m[k]) * mV[k]) / (2.0 * in.m[k] + bSum[k] * dt);
        mDx[k] = (-(dt * mV[k]) - 2.0 * mX[k]) / 2.0;
    }
}

void MechanicM3load1D::initialize()
{
    for (int k = 0; k < 3; ++k) {
        mpF[k] = getSafeNodeDataPtr(mpPm[k], NodeMechanic::Force);
        mpX[k] = getSafeNodeDataPtr(mpPm[k], NodeMechanic::Position);
        mpV[k] = getSafeNodeDataPtr(mpPm[k], NodeMechanic::Velocity);
        mpC[k] = getSafeNodeDataPtr(mpPm[k], NodeMechanic::WaveVariable);
        mpZc[k] = getSafeNodeDataPtr(mpPm[k], NodeMechanic::CharImpedance);
        mpMe[k] = getSafeNodeDataPtr(mpPm[k], NodeMechanic::EquivalentMass);
        mF[k] = *mpF[k];
        mX[k] = *mpX[k];
        mV[k] = *mpV[k];
    }

    mJac.create(9, 9);
    mEq.create(9);
    mState.create(9);
    mSingularReported = false;

    const Inputs in = readInputs();
    computeDelayedParts(in, loads(in));
}

void MechanicM3load1D::simulateOneTimestep()
{
    // Read the node values and inputs.
    double c[3], Zc[3];
    for (int k = 0; k < 3; ++k) {
        c[k] = *mpC[k];
        Zc[k] = *mpZc[k];
    }
    const Inputs in = readInputs();
    const double dt = mTimestep;
    const double bSum[3] = {in.b[0] + in.b12 + in.b13, in.b[1] + in.b12, in.b[2] + in.b13};
    double den[3];
    for (int k = 0; k < 3; ++k) den[k] = 2.0 * in.m[k] + bSum[k] * dt;

    for (int k = 0; k < 3; ++k) {
        mState[k] = mV[k];
        mState[3 + k] = mX[k];
        mState[6 + k] = mF[k];
    }

    // Equations. Per mass k, with xp = dt v / 2 - Dx the unlimited position:
    //   v = gate * (dt g / (2m + B dt) - Dv),  gate = dxLimit(limit(xp)) (1, or ~0 at a stop),
    //   x = limit(xp, xMin, xMax),
    //   f = c + Zc v.
    for (int iter = 1; iter <= 2; ++iter) {
        const Loads l = loads(in);
        for (int r = 0; r < 9; ++r) {
            for (int col = 0; col < 9; ++col) mJac[r][col] = 0.0;
        }
        for (int k = 0; k < 3; ++k) {
            const double xp = (dt * mV[k]) / 2.0 - mDx[k];
            const double xl = limit(xp, in.xMin[k], in.xMax[k]);
            const double gate = dxLimit(xl, in.xMin[k], in.xMax[k]);

            mEq[k] = mV[k] - gate * ((dt * l.g[k]) / den[k] - mDv[k]);
            mEq[3 + k] = mX[k] - xl;
            mEq[6 + k] = -c[k] + mF[k] - mV[k] * Zc[k];

            for (int j = 0; j < 3; ++j) mJac[k][j] = -(dt * gate * l.dg[k][j]) / den[k];
            mJac[k][k] += 1.0;
            mJac[k][6 + k] = (dt * gate) / den[k];
            mJac[3 + k][k] = -(dt * dxLimit(xp, in.xMin[k], in.xMax[k])) / 2.0;
            mJac[3 + k][3 + k] = 1.0;
            mJac[6 + k][k] = -Zc[k];
            mJac[6 + k][6 + k] = 1.0;
        }

        if (!mSolver.solve(mJac, mEq, mState, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("MechanicM3load1D: singular Jacobian");
        }
        for (int k = 0; k < 3; ++k) {
            mV[k] = mState[k];
            mX[k] = mState[3 + k];
            mF[k] = mState[6 + k];
        }
    }

    // Outputs, with the friction forces at the final velocities.
    const Loads l = loads(in);
    double posOut[3], velOut[3], fricOut[3];
    for (int k = 0; k < 3; ++k) {
        posOut[k] = in.offset[k] - in.dir[k] * mX[k];
        velOut[k] = -(in.dir[k] * mV[k]);
        fricOut[k] = in.dir[k] * (in.b[k] * mV[k] - l.fr[k]);
    }
    const double fric12 = -(in.b12 * (mV[0] - mV[1])) + l.fr12;
    const double fric13 = -(in.b13 * (mV[0] - mV[2])) + l.fr13;

    computeDelayedParts(in, l);

    // Write the node values and outputs.
    for (int k = 0; k < 3; ++k) {
        *mpF[k] = mF[k];
        *mpX[k] = mX[k];
        *mpV[k] = mV[k];
        *mpMe[k] = in.m[k];
        *mpPosOut[k] = posOut[k];
        *mpVelOut[k] = velOut[k];
        *mpFricOut[k] = fricOut[k];
    }
    *mpFric12Out = fric12;
    *mpFric13Out = fric13;
}

TLMHUB_REGISTER_COMPONENT(MechanicM3load1D, "Mechanic")

} // namespace tlmhub
