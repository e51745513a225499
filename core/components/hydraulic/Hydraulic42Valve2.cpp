#include "core/components/hydraulic/Hydraulic42Valve2.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void Hydraulic42Valve2::addEdgeInputs()
{
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_pb", "Fraction of spool circumference that is opening P-B", "-", 1.0, &mpFpb);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpFbt);
}

HydraulicFourWaySpoolValveBase::Edges Hydraulic42Valve2::edges(double xv, double xvmax) const
{
    Edges K;
    K.pa = edge(*mpFpa, xv);
    K.pb = edge(*mpFpb, xvmax - xv);
    K.at = edge(*mpFat, xvmax - xv);
    K.bt = edge(*mpFbt, xv);
    return K;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic42Valve2, "Hydraulic")

} // namespace tlmhub
