#include "core/components/mechanic/MechanicTranslationalSpring.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalSpring::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    addInputVariable("k", "Spring coefficient", "N/m", 100.0, &mpK);
    addConstant("alpha", "Numerical damping (filter factor, 0 <= alpha < 1)", "-", 0.0, mAlpha);
}

void MechanicTranslationalSpring::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP2_f = getSafeNodeDataPtr(mpP2, NodeMechanic::Force);
    mpP2_v = getSafeNodeDataPtr(mpP2, NodeMechanic::Velocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeMechanic::CharImpedance);

    const double Zc = (*mpK) * mTimestep / (1.0 - mAlpha);
    // Initial waves consistent with the start forces and velocities of the far end.
    *mpP1_c = *mpP2_f + Zc * (*mpP2_v);
    *mpP2_c = *mpP1_f + Zc * (*mpP1_v);
    *mpP1_Zc = Zc;
    *mpP2_Zc = Zc;
}

void MechanicTranslationalSpring::simulateOneTimestep()
{
    const double v1 = *mpP1_v;
    const double lastc1 = *mpP1_c;
    const double v2 = *mpP2_v;
    const double lastc2 = *mpP2_c;

    const double Zc = (*mpK) * mTimestep / (1.0 - mAlpha);

    const double c1 = (lastc2 + 2.0 * Zc * v2) * (1.0 - mAlpha) + mAlpha * lastc1;
    const double c2 = (lastc1 + 2.0 * Zc * v1) * (1.0 - mAlpha) + mAlpha * lastc2;

    *mpP1_c = c1;
    *mpP1_Zc = Zc;
    *mpP2_c = c2;
    *mpP2_Zc = Zc;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalSpring, "Mechanic")

} // namespace tlmhub
