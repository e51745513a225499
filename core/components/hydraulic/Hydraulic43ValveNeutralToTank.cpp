#include "core/components/hydraulic/Hydraulic43ValveNeutralToTank.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Hydraulic43ValveNeutralToTank::addCentre(Edges& K, double Kc) const
{
    K.at += Kc;
    K.bt += Kc;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic43ValveNeutralToTank, "Hydraulic")

} // namespace tlmhub
