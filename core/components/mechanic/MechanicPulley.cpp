#include "core/components/mechanic/MechanicPulley.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicPulley::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    addConstant("m", "Mass", "kg", 1.0, mMass);
    addInputVariable("B", "Viscous friction coefficient", "Ns/m", 10.0, &mpB);
}

void MechanicPulley::initialize()
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

    const double f1 = 2.0 * (*mpP1_f);
    const double x1 = (*mpP1_x) / 2.0;
    const double v1 = (*mpP1_v) / 2.0;
    const double f2 = *mpP2_f;
    const double B = *mpB;

    mDenX[0] = 0.0;
    mDenX[1] = B;
    mDenX[2] = mMass;
    mFilterX.initialize(mTimestep, mNumX, mDenX, f1 - f2, -x1, -1.5e300, 1.5e300, -v1);
    mDenV[0] = B;
    mDenV[1] = mMass;
    mFilterV.initialize(mTimestep, mNumV, mDenV, f1 - f2, -v1);

    *mpP1_me = mMass;
    *mpP2_me = mMass;
}

void MechanicPulley::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;
    const double B = *mpB;

    mDenX[1] = B + 4.0 * Zx1 + Zx2;
    mDenV[0] = B + 4.0 * Zx1 + Zx2;
    mFilterX.setDen(mDenX);
    mFilterV.setDen(mDenV);

    const double x2 = mFilterX.update(2.0 * c1 - c2);
    const double v2 = mFilterV.update(2.0 * c1 - c2);

    const double f2 = c2 + Zx2 * v2;
    const double v1 = -2.0 * v2;
    const double x1 = -2.0 * x2;
    const double f1 = c1 + Zx1 * v1;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP2_f = f2;
    *mpP2_x = x2;
    *mpP2_v = v2;
}

TLMHUB_REGISTER_COMPONENT(MechanicPulley, "Mechanic")

} // namespace tlmhub
