#include "core/components/mechanic/MechanicRotationalInertia.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicRotationalInertia::configure()
{
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);
    addConstant("J", "Moment of inertia", "kg m^2", 0.1, mJ);
    addInputVariable("B", "Viscous friction coefficient", "Nm s/rad", 10.0, &mpB);
    addInputVariable("k", "Spring coefficient", "Nm/rad", 0.0, &mpK);
    addInputVariable("a_min", "Minimum angle of P2", "rad", -1.0e300, &mpAMin);
    addInputVariable("a_max", "Maximum angle of P2", "rad", 1.0e300, &mpAMax);
}

void MechanicRotationalInertia::initialize()
{
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Torque);
    mpP1_a = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Angle);
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);
    mpP2_T = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Torque);
    mpP2_a = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Angle);
    mpP2_w = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::AngularVelocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::CharImpedance);

    const double t1 = *mpP1_T, t2 = *mpP2_T;
    const double a1 = *mpP1_a, a2 = *mpP2_a;
    const double w1 = *mpP1_w;
    const double B = *mpB, k = *mpK;

    // den[0] = k is set only here (the step never changes it).
    mDenX[0] = k;
    mDenX[1] = B;
    mDenX[2] = mJ;
    mFilterX.initialize(mTimestep, mNumX, mDenX, t1 - t2, -a1, -1.5e300, 1.5e300, -w1);

    mDenV[0] = B;
    mDenV[1] = mJ;
    mFilterV.initialize(mTimestep, mNumV, mDenV, t1 - t2 - k * a2, -w1);
}

void MechanicRotationalInertia::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;
    const double B = *mpB, k = *mpK;

    mDenX[1] = B + Zx1 + Zx2;
    mDenV[0] = B + Zx1 + Zx2;
    mFilterX.setDen(mDenX);
    mFilterV.setDen(mDenV);

    double a2 = mFilterX.update(c1 - c2);
    double w2 = mFilterV.update(c1 - c2 - k * a2);

    if (a2 < *mpAMin) {
        a2 = *mpAMin;
        w2 = 0.0;
        mFilterX.initializeValues(c1 - c2, a2);
        mFilterV.initializeValues(c1 - c2, 0.0);
    }
    if (a2 > *mpAMax) {
        a2 = *mpAMax;
        w2 = 0.0;
        mFilterX.initializeValues(c1 - c2, a2);
        mFilterV.initializeValues(c1 - c2, 0.0);
    }

    const double w1 = -w2;
    const double a1 = -a2;
    const double t1 = c1 + Zx1 * w1;
    const double t2 = c2 + Zx2 * w2;

    *mpP1_T = t1;
    *mpP1_a = a1;
    *mpP1_w = w1;
    *mpP2_T = t2;
    *mpP2_a = a2;
    *mpP2_w = w2;
}

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInertia, "Mechanic")

} // namespace tlmhub
