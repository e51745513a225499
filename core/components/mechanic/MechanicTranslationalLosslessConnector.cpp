#include "core/components/mechanic/MechanicTranslationalLosslessConnector.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalLosslessConnector::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
}

void MechanicTranslationalLosslessConnector::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP2_f = getSafeNodeDataPtr(mpP2, NodeMechanic::Force);
    mpP2_x = getSafeNodeDataPtr(mpP2, NodeMechanic::Position);
    mpP2_v = getSafeNodeDataPtr(mpP2, NodeMechanic::Velocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanic::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanic::CharImpedance);

    const double x1 = *mpP1_x, x2 = *mpP2_x;
    const double v1 = *mpP1_v, v2 = *mpP2_v;
    mLength = x1 + x2;
    mIntegrator.initialize(mTimestep, -v1, -x1 + mLength);

    if (v1 != -v2) {
        addDebugMessage("Start velocities of P1 and P2 do not match (v1 != -v2).");
    }
}

void MechanicTranslationalLosslessConnector::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;

    const double v2 = (c1 - c2) / (Zx1 + Zx2);
    const double v1 = -v2;
    const double x2 = mIntegrator.update(v2);
    const double x1 = -x2 + mLength;
    const double f1 = c1 + Zx1 * v1;
    const double f2 = c2 + Zx2 * v2;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP2_f = f2;
    *mpP2_x = x2;
    *mpP2_v = v2;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalLosslessConnector, "Mechanic")

} // namespace tlmhub
