#include "core/components/mechanic/Forks.h"

#include "core/ComponentFactory.h"

#include <array>
#include <cmath>

namespace tlmhub {

void Forks::configure()
{
    addConstant("r", "Pinion radius (traverse)", "m", 0.1, mR);
    addConstant("m", "Mass (traverse)", "kg", 100.0, mM);
    addConstant("sl", "Piston stroke", "m", 1.0, mSl);
    addInputVariable("B", "Viscous friction (traverse)", "Ns/m", 10.0, &mpB);
    addInputVariable("k", "Spring coefficient (traverse)", "N/m", 0.0, &mpK);
    addInputVariable("x_min", "Minimum position (traverse)", "m", -0.6, &mpXMin);
    addInputVariable("x_max", "Maximum position (traverse)", "m", 0.6, &mpXMax);
    addOutputVariable("x", "Position (traverse)", "m", -0.6, &mpX);
    addConstant("r2", "Lever radius (rotation)", "m", 0.1, mRrot);
    addConstant("J", "Inertia (rotation)", "kgm^2", 0.2, mJ);
    addInputVariable("Kfrot", "Dry friction (rotation)", "Nm", 10.0, &mpKfrot);
    addInputVariable("Brot", "Viscous friction (rotation)", "Nms/rad", 10.0, &mpBrot);
    addInputVariable("krot", "Spring coefficient (rotation)", "Nm/rad", 0.0, &mpKrot);
    addInputVariable("a_min", "Minimum angle (rotation)", "rad", -1.5707963267949, &mpAMin);
    addInputVariable("a_max", "Maximum angle (rotation)", "rad", 1.5707963267949, &mpAMax);
    addOutputVariable("a", "Angle (rotation)", "rad", 1.5707963267949, &mpA);
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    mpP3 = addPowerPort("P3", NodeType::Mechanic);
}

void Forks::initialize()
{
    mpP1_a = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Angle);
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Torque);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);
    mpP2_x = getSafeNodeDataPtr(mpP2, NodeMechanic::Position);
    mpP2_v = getSafeNodeDataPtr(mpP2, NodeMechanic::Velocity);
    mpP2_f = getSafeNodeDataPtr(mpP2, NodeMechanic::Force);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeMechanic::CharImpedance);
    mpP3_x = getSafeNodeDataPtr(mpP3, NodeMechanic::Position);
    mpP3_v = getSafeNodeDataPtr(mpP3, NodeMechanic::Velocity);
    mpP3_f = getSafeNodeDataPtr(mpP3, NodeMechanic::Force);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeMechanic::WaveVariable);
    mpP3_Zc = getSafeNodeDataPtr(mpP3, NodeMechanic::CharImpedance);

    const double x = *mpX;
    const double a = *mpA;
    // Hopsan seeds the traverse filters' input with the P1 *angle* over r, and passes the
    // start position / angle as the filters' start derivative (no effect on a first run).
    const double u1 = *mpP1_a / mR;
    mTraversePosition.initialize(mTimestep, std::array<double, 3>{1.0, 0.0, 0.0},
                                 std::array<double, 3>{*mpK, *mpB, mM}, u1, x, -1.5e300, 1.5e300, x);
    mTraverseSpeed.initialize(mTimestep, std::array<double, 2>{1.0, 0.0}, std::array<double, 2>{*mpB, mM}, u1, 0.0);
    const double tiltTorque = (*mpP2_f - *mpP3_f) * mRrot;
    mTiltAngle.initialize(mTimestep, std::array<double, 3>{1.0, 0.0, 0.0},
                          std::array<double, 3>{*mpKrot, *mpBrot, mJ}, tiltTorque, a, -1.5e300, 1.5e300, a);
    mTiltSpeed.initialize(mTimestep, std::array<double, 2>{1.0, 0.0}, std::array<double, 2>{*mpBrot, mJ},
                          tiltTorque - *mpKrot * a, 0.0);
    // Both pistons start at the same position (the step gives P2 the mirrored one).
    *mpP2_x = a * mRrot - mSl / 2.0;
    *mpP3_x = a * mRrot - mSl / 2.0;
}

void Forks::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double c3 = *mpP3_c, Zc3 = *mpP3_Zc;
    const double k = *mpK, B = *mpB, krot = *mpKrot, Brot = *mpBrot;
    // Hopsan reads its local angle a1 and piston position x3 here before assigning them
    // (only multiplied by k and krot, 0 by default); the previous step's values are used.
    const double a1Prev = *mpP1_a;
    const double x3Prev = *mpP3_x;

    // Traverse: m x'' + (B + Zc1) x' + k x = c1 / r, between x_min and x_max.
    mTraversePosition.setDen(std::array<double, 3>{k, B + Zc1, mM});
    mTraverseSpeed.setDen(std::array<double, 2>{B + Zc1, mM});
    double x = mTraversePosition.update(c1 / mR);
    double v = mTraverseSpeed.update(c1 / mR - k * a1Prev * mR);
    if (x < *mpXMin || x > *mpXMax) {
        x = x < *mpXMin ? *mpXMin : *mpXMax;
        v = 0.0;
        mTraversePosition.initializeValues(c1 / mR, x);
        mTraverseSpeed.initializeValues(c1 / mR, 0.0);
    }
    const double w1 = -v / mR;

    // Tilt: J a'' + (Brot + Zc2 + Zc3) a' + krot a = (c2 - c3) r2 + F_dry, between a_min and
    // a_max; the dry friction uses P2's speed of the previous step.
    const double dryFriction = *mpKfrot * std::tanh(*mpP2_v / mRrot);
    const double torque = (c2 - c3) * mRrot + dryFriction;
    mTiltAngle.setDen(std::array<double, 3>{krot, Brot + Zc2 + Zc3, mJ});
    mTiltSpeed.setDen(std::array<double, 2>{Brot + Zc2 + Zc3, mJ});
    double a = mTiltAngle.update(torque);
    double w = mTiltSpeed.update(torque - krot * x3Prev / mRrot);
    if (a < *mpAMin || a > *mpAMax) {
        a = a < *mpAMin ? *mpAMin : *mpAMax;
        w = 0.0;
        mTiltAngle.initializeValues(torque, a);
        mTiltSpeed.initializeValues(torque, 0.0);
    }
    const double v2 = -w * mRrot;
    const double v3 = w * mRrot;

    *mpP1_T = c1 + Zc1 * w1;
    *mpP1_a = -x / mR;
    *mpP1_w = w1;
    *mpX = x;
    *mpP2_f = c2 + Zc2 * v2;
    *mpP2_x = -a * mRrot - mSl / 2.0;
    *mpP2_v = v2;
    *mpP3_f = c3 + Zc3 * v3;
    *mpP3_x = a * mRrot - mSl / 2.0;
    *mpP3_v = v3;
    *mpA = a;
}

TLMHUB_REGISTER_COMPONENT(Forks, "Mechanic")

} // namespace tlmhub
