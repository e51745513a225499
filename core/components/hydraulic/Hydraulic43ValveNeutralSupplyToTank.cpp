#include "core/components/hydraulic/Hydraulic43ValveNeutralSupplyToTank.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Hydraulic43ValveNeutralSupplyToTank::addCentre(Edges& K, double Kc) const
{
    K.pt += Kc;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic43ValveNeutralSupplyToTank, "Hydraulic")

} // namespace tlmhub
