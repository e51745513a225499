#include "core/components/mechanic/MechanicTorsionalSpring.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTorsionalSpring::configure()
{
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);
    addConstant("k", "Spring constant", "Nm/rad", 100.0, mK);
}

void MechanicTorsionalSpring::initialize()
{
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);
    mpP2_w = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::AngularVelocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::CharImpedance);

    // Only the impedance is set; the waves keep their start values.
    mZx = mK * mTimestep;
    *mpP1_Zx = mZx;
    *mpP2_Zx = mZx;
}

void MechanicTorsionalSpring::simulateOneTimestep()
{
    const double w1 = *mpP1_w;
    const double lastc1 = *mpP1_c;
    const double w2 = *mpP2_w;
    const double lastc2 = *mpP2_c;

    const double c1 = lastc2 + 2.0 * mZx * w2;
    const double c2 = lastc1 + 2.0 * mZx * w1;

    *mpP1_c = c1;
    *mpP2_c = c2;
}

TLMHUB_REGISTER_COMPONENT(MechanicTorsionalSpring, "Mechanic")

} // namespace tlmhub
