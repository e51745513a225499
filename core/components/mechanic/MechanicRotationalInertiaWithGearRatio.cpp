#include "core/components/mechanic/MechanicRotationalInertiaWithGearRatio.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>

namespace tlmhub {

void MechanicRotationalInertiaWithGearRatio::configure()
{
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);
    addInputVariable("omega", "Gear ratio", "", 1.0, &mpOmega);
    addInputVariable("B", "Viscous friction coefficient", "Nm s/rad", 10.0, &mpB);
    addConstant("J", "Moment of inertia", "kg m^2", 1.0, mJ);
}

void MechanicRotationalInertiaWithGearRatio::initialize()
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
    const double a2 = *mpP2_a, w2 = *mpP2_w;
    const double B = *mpB;
    const double U = *mpOmega;

    mDenTheta[0] = 0.0;
    mDenTheta[1] = B;
    mDenTheta[2] = mJ;
    mFilterTheta.initialize(mTimestep, mNumTheta, mDenTheta, U * t1 - t2, a2, -1.5e300, 1.5e300, w2);

    mDenOmega[0] = B;
    mDenOmega[1] = mJ;
    mFilterOmega.initialize(mTimestep, mNumOmega, mDenOmega, U * t1 - t2, w2);
}

void MechanicRotationalInertiaWithGearRatio::simulateOneTimestep()
{
    const double U = *mpOmega;
    const double B = *mpB;
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;

    const double BB = B + U * U * Zx1 + Zx2;
    mDenTheta[1] = BB;
    mDenOmega[0] = BB;
    mFilterTheta.setDen(mDenTheta);
    mFilterOmega.setDen(mDenOmega);

    const double TT = U * c1 - c2;
    const double a2 = mFilterTheta.update(TT);
    const double w2 = mFilterOmega.update(TT);

    const double t2 = c2 + Zx2 * w2;
    const double w1 = -U * w2;
    const double a1 = -U * a2;
    const double t1 = c1 + Zx1 * w1;

    *mpP1_T = t1;
    *mpP1_a = a1;
    *mpP1_w = w1;
    *mpP2_T = t2;
    *mpP2_a = a2;
    *mpP2_w = w2;
}

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInertiaWithGearRatio, "Mechanic")

} // namespace tlmhub
