#include "core/components/mechanic/MechanicCylinderBlockWithSwashPlate.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void MechanicCylinderBlockWithSwashPlate::configure()
{
    mpP1 = addPowerMultiPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);

    addInputVariable("B", "Viscous friction", "Nms/rad", 10.0, &mpB);
    addInputVariable("r", "Swivel radius", "m", 0.05, &mpR);
    addInputVariable("theta_offset", "Angle offset", "m", 0.0, &mpThetaOffset);
    addInputVariable("angle", "Swash plate angle", "rad", 0.0, &mpAngle);
    addOutputVariable("torque", "Torque", "Nm", 0.0, &mpTorque);
    addOutputVariable("movement", "Angular velocity", "rad/s", 0.0, &mpMovement);

    addConstant("J", "Inertia of cylinder block", "kg m^2", 0.1, mJ);
    addConstant("m_p", "Mass of each piston", "kg", 0.001, mMp);
    addConstant("r_p", "Piston radius", "m", 0.01, mRp);
}

void MechanicCylinderBlockWithSwashPlate::initialize()
{
    mN = getNumPorts(mpP1);
    mvpP1_f.assign(mN, nullptr);
    mvpP1_x.assign(mN, nullptr);
    mvpP1_v.assign(mN, nullptr);
    mvpP1_c.assign(mN, nullptr);
    mvpP1_Zc.assign(mN, nullptr);
    mvpP1_me.assign(mN, nullptr);
    mC1.assign(mN, 0.0);
    mZc1.assign(mN, 0.0);
    // Every piston node is zeroed here, overriding the pistons' start values (so the
    // stroke centre startX below is 0 whatever P3#Position the pistons were given).
    for (std::size_t i = 0; i < mN; ++i) {
        mvpP1_f[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::Force, 0.0);
        mvpP1_x[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::Position, 0.0);
        mvpP1_v[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::Velocity, 0.0);
        mvpP1_c[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::WaveVariable, 0.0);
        mvpP1_Zc[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::CharImpedance, 0.0);
        mvpP1_me[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::EquivalentMass, 0.0);
    }
    for (std::size_t i = 0; i < mN; ++i) *mvpP1_me[i] = 0.02;
    mpP2_t = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Torque);
    mpP2_a = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Angle);
    mpP2_w = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::AngularVelocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::CharImpedance);

    mStartX = (mN > 0) ? *mvpP1_x[0] : 0.0;
    const double t2 = *mpP2_t, a2 = *mpP2_a, w2 = *mpP2_w;
    mA2 = a2;

    const double B = *mpB;
    const double numX[3] = {1.0, 0.0, 0.0};
    const double denX[3] = {0.0, B, mJ};
    mFilterX.initialize(mTimestep, numX, denX, -t2, a2);
    const double numV[2] = {1.0, 0.0};
    const double denV[2] = {B, mJ};
    mFilterV.initialize(mTimestep, numV, denV, -t2, w2);
    // The reference then adds the piston inertia to J, but the filters already hold
    // the original J, so that has no effect and is left out.
}

void MechanicCylinderBlockWithSwashPlate::simulateOneTimestep()
{
    const double thetaOffset = *mpThetaOffset, r = *mpR, B = *mpB, angle = *mpAngle;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;

    const double ta = std::tan(angle);
    const double s = r * ta;
    const double diff = 2.0 * pi / static_cast<double>(mN);
    const double a1 = -mA2;

    // Piston forces reduced to the shaft.
    double cp = 0.0, Zp = 0.0;
    for (std::size_t i = 0; i < mN; ++i) {
        mC1[i] = *mvpP1_c[i];
        mZc1[i] = *mvpP1_Zc[i];
        const double co = std::cos(a1 - thetaOffset - diff * static_cast<double>(i));
        cp += mC1[i] * ta * r * co;
        Zp += mZc1[i] * ta * r * co * ta * r * co;
    }

    const double denX[3] = {0.0, B + Zp + Zc2, mJ};
    const double denV[2] = {B + Zp + Zc2, mJ};
    mFilterX.setDen(denX);
    mFilterV.setDen(denV);

    mA2 = mFilterX.update(cp - c2);
    const double w2 = mFilterV.update(cp - c2);
    const double t2 = c2 + Zc2 * w2;
    const double w1 = -w2;

    for (std::size_t i = 0; i < mN; ++i) {
        const double a = a1 - thetaOffset - diff * static_cast<double>(i);
        const double v1 = s * std::cos(a) * w1;
        const double x1 = mStartX + s * std::sin(a);
        const double f1 = mC1[i] + mZc1[i] * v1;
        *mvpP1_f[i] = f1;
        *mvpP1_x[i] = x1;
        *mvpP1_v[i] = v1;
    }

    *mpTorque = -t2;
    *mpMovement = w1;
    *mpP2_t = t2;
    *mpP2_a = mA2;
    *mpP2_w = w2;
}

TLMHUB_REGISTER_COMPONENT(MechanicCylinderBlockWithSwashPlate, "Mechanic")

} // namespace tlmhub
