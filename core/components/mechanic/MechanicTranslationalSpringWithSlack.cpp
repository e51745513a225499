#include "core/components/mechanic/MechanicTranslationalSpringWithSlack.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalSpringWithSlack::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    addInputVariable("k", "Spring coefficient", "N/m", 100.0, &mpK);
}

void MechanicTranslationalSpringWithSlack::initialize()
{
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP2_x = getSafeNodeDataPtr(mpP2, NodeMechanic::Position);
    mpP2_v = getSafeNodeDataPtr(mpP2, NodeMechanic::Velocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeMechanic::CharImpedance);

    // Waves keep their start values.
    *mpP1_Zc = (*mpK) * mTimestep;
    *mpP2_Zc = (*mpK) * mTimestep;
}

void MechanicTranslationalSpringWithSlack::simulateOneTimestep()
{
    const double x1 = *mpP1_x;
    const double x2 = *mpP2_x;

    double c1, c2, Zc;
    if (x1 + x2 > 0.0) {
        c1 = 0.0;
        c2 = 0.0;
        Zc = 0.0;
    } else {
        const double v1 = *mpP1_v, lastc1 = *mpP1_c;
        const double v2 = *mpP2_v, lastc2 = *mpP2_c;
        Zc = (*mpK) * mTimestep;
        c1 = lastc2 + 2.0 * Zc * v2;
        c2 = lastc1 + 2.0 * Zc * v1;
    }

    *mpP1_c = c1;
    *mpP1_Zc = Zc;
    *mpP2_c = c2;
    *mpP2_Zc = Zc;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalSpringWithSlack, "Mechanic")

} // namespace tlmhub
