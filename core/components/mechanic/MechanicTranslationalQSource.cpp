#include "core/components/mechanic/MechanicTranslationalQSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalQSource::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    addInputVariable("in_f", "Force", "N", 0.0, &mpInF);
    addInputVariable("in_v", "Velocity", "m/s", 0.0, &mpInV);
    addInputVariable("in_x", "Position", "m", 0.0, &mpInX);
    addInputVariable("in_em", "Equivalent mass", "kg", 1.0, &mpInEm);
}

void MechanicTranslationalQSource::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_me = getSafeNodeDataPtr(mpP1, NodeMechanic::EquivalentMass);
    simulateOneTimestep();
}

void MechanicTranslationalQSource::simulateOneTimestep()
{
    *mpP1_f = *mpInF;
    *mpP1_v = *mpInV;
    *mpP1_x = *mpInX;
    *mpP1_me = *mpInEm;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalQSource, "Mechanic")

} // namespace tlmhub
