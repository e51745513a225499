#include "core/components/hydraulic/Hydraulic42Valve.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Hydraulic42Valve::addEdgeInputs()
{
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpFbt);
}

HydraulicFourWaySpoolValveBase::Edges Hydraulic42Valve::edges(double xv, double /*xvmax*/) const
{
    Edges K;
    K.pa = edge(*mpFpa, xv);
    K.bt = edge(*mpFbt, xv);
    return K;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic42Valve, "Hydraulic")

} // namespace tlmhub
