#include "core/components/mechanic/MechanicFixedPosition.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicFixedPosition::configure()
{
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    addConstant("m_e", "Equivalent mass", "kg", 1.0, mMe);
}

void MechanicFixedPosition::initialize()
{
    mpPm1_f = getSafeNodeDataPtr(mpPm1, NodeMechanic::Force);
    mpPm1_v = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpPm1_c = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpPm1_me = getSafeNodeDataPtr(mpPm1, NodeMechanic::EquivalentMass);

    // Position is left at its start value for the whole run.
    *mpPm1_v = 0.0;
    *mpPm1_me = mMe;
}

void MechanicFixedPosition::simulateOneTimestep()
{
    *mpPm1_f = *mpPm1_c;
}

TLMHUB_REGISTER_COMPONENT(MechanicFixedPosition, "Mechanic")

} // namespace tlmhub
