#include "core/components/mechanic/MechanicFreeLengthWall.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicFreeLengthWall::configure()
{
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    addInputVariable("B", "Viscous friction (should be non-zero)", "Ns/m", 0.001, &mpB);
    addConstant("m_e", "Equivalent mass", "kg", 1.0, mMe);
    addConstant("stop_pos", "Stop position (positive direction out of the component)", "m", 0.0,
                mStopPos);
}

void MechanicFreeLengthWall::initialize()
{
    mpPm1_f = getSafeNodeDataPtr(mpPm1, NodeMechanic::Force);
    mpPm1_x = getSafeNodeDataPtr(mpPm1, NodeMechanic::Position);
    mpPm1_v = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpPm1_c = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpPm1_Zx = getSafeNodeDataPtr(mpPm1, NodeMechanic::CharImpedance);
    mpPm1_me = getSafeNodeDataPtr(mpPm1, NodeMechanic::EquivalentMass);

    const double B = *mpB;
    // Position: 1/(B s); velocity: 1/B. The step sets the real denominators (B + Zx)
    // before the first update, so a zero B here does no harm.
    mDenX[0] = 0.0;
    mDenX[1] = B;
    mDenV[0] = B;
    mDenV[1] = 0.0;
    mFilterX.initialize(mTimestep, mNum, mDenX, -(*mpPm1_c), *mpPm1_x);
    mFilterV.initialize(mTimestep, mNum, mDenV, -(*mpPm1_c), *mpPm1_v);

    *mpPm1_me = mMe;
}

void MechanicFreeLengthWall::simulateOneTimestep()
{
    const double c1 = *mpPm1_c;
    const double Zx1 = *mpPm1_Zx;
    const double B = *mpB;

    mDenX[0] = 0.0;
    mDenX[1] = B + Zx1;
    mDenV[0] = B + Zx1;
    mDenV[1] = 0.0;
    mFilterX.setDen(mDenX);
    mFilterV.setDen(mDenV);

    double x1 = mFilterX.update(-c1);
    double v1 = mFilterV.update(-c1);
    double f1;

    if (x1 <= mStopPos) {
        // In contact: held at the stop, force taken from the incoming wave.
        x1 = mStopPos;
        v1 = 0.0;
        mFilterX.initializeValues(-c1, x1);
        mFilterV.initializeValues(-c1, v1);
        f1 = c1 + Zx1 * v1;
    } else {
        f1 = 0.0;
    }

    *mpPm1_f = f1;
    *mpPm1_x = x1;
    *mpPm1_v = v1;
}

TLMHUB_REGISTER_COMPONENT(MechanicFreeLengthWall, "Mechanic")

} // namespace tlmhub
