#include "core/components/mechanic/MechanicTranslationalMass.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalMass::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    addInputVariable("B", "Viscous friction coefficient", "Ns/m", 10.0, &mpB);
    addInputVariable("k", "Spring constant", "N/m", 0.0, &mpK);
    addInputVariable("x_min", "Minimum position of P2", "m", -1.0e300, &mpXMin);
    addInputVariable("x_max", "Maximum position of P2", "m", 1.0e300, &mpXMax);
    addConstant("m", "Mass", "kg", 100.0, mMass);
}

void MechanicTranslationalMass::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP1_me = getSafeNodeDataPtr(mpP1, NodeMechanic::EquivalentMass);
    mpP2_f = getSafeNodeDataPtr(mpP2, NodeMechanic::Force);
    mpP2_x = getSafeNodeDataPtr(mpP2, NodeMechanic::Position);
    mpP2_v = getSafeNodeDataPtr(mpP2, NodeMechanic::Velocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanic::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanic::CharImpedance);
    mpP2_me = getSafeNodeDataPtr(mpP2, NodeMechanic::EquivalentMass);

    const double f1 = *mpP1_f, f2 = *mpP2_f;
    const double x1 = *mpP1_x, x2 = *mpP2_x;
    const double v2 = *mpP2_v;
    const double B = *mpB, k = *mpK;

    mLength = x1 + x2;

    mDen[0] = k;
    mDen[1] = B;
    mDen[2] = mMass;
    mFilterX.initialize(mTimestep, mNum, mDen, f1 - f2, x2, -1.5e300, 1.5e300, v2);

    mDenV[0] = B;
    mDenV[1] = mMass;
    mFilterV.initialize(mTimestep, mNumV, mDenV, f1 - f2 - k * x2, v2);

    *mpP1_me = mMass;
    *mpP2_me = mMass;

    // The two ends of a rigid body must start with opposite velocities.
    if (*mpP1_v != -*mpP2_v) {
        stopSimulation("Start velocities of P1 and P2 must be opposite (v1 = -v2).");
    }
}

void MechanicTranslationalMass::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;
    const double k = *mpK, B = *mpB;

    mDen[0] = k;
    mDen[1] = B + Zx1 + Zx2;
    mDen[2] = mMass;
    mDenV[0] = B + Zx1 + Zx2;
    mDenV[1] = mMass;
    mFilterX.setDen(mDen);
    mFilterV.setDen(mDenV);

    double x2 = mFilterX.update(c1 - c2);
    double v2 = mFilterV.update(c1 - c2 - k * x2);

    // End stops: clamp and restart both filters at rest at the stop.
    if (x2 < *mpXMin) {
        x2 = *mpXMin;
        v2 = 0.0;
        mFilterX.initializeValues(c1 - c2, x2);
        mFilterV.initializeValues(c1 - c2, 0.0);
    }
    if (x2 > *mpXMax) {
        x2 = *mpXMax;
        v2 = 0.0;
        mFilterX.initializeValues(c1 - c2, x2);
        mFilterV.initializeValues(c1 - c2, 0.0);
    }

    const double v1 = -v2;
    const double x1 = -x2 + mLength;
    const double f1 = c1 + Zx1 * v1;
    const double f2 = c2 + Zx2 * v2;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP1_me = mMass;
    *mpP2_f = f2;
    *mpP2_x = x2;
    *mpP2_v = v2;
    *mpP2_me = mMass;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalMass, "Mechanic")

} // namespace tlmhub
