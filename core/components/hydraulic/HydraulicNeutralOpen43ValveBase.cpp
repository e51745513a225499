#include "core/components/hydraulic/HydraulicNeutralOpen43ValveBase.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicNeutralOpen43ValveBase::addEdgeInputs()
{
    addInputVariable("p_c", "Fraction of displacement when central position is open", "-", 0.02, &mpPc);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_pb", "Fraction of spool circumference that is opening P-B", "-", 1.0, &mpFpb);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpFbt);
    addInputVariable("f_c", "Fraction of spool circumference opening at neutral position", "-", 0.1, &mpFc);
    addInputVariable("x_pa", "Spool Overlap From Port P To A", "m", -1e-6, &mpXpa);
    addInputVariable("x_pb", "Spool Overlap From Port P To B", "m", -1e-6, &mpXpb);
    addInputVariable("x_at", "Spool Overlap From Port A To T", "m", -1e-6, &mpXat);
    addInputVariable("x_bt", "Spool Overlap From Port B To T", "m", -1e-6, &mpXbt);
}

HydraulicFourWaySpoolValveBase::Edges HydraulicNeutralOpen43ValveBase::edges(double xv, double xvmax) const
{
    Edges K;
    K.pa = edge(*mpFpa, std::max(xv - *mpXpa, 0.0));
    K.pb = edge(*mpFpb, std::max(-xv - *mpXpb, 0.0));
    K.at = edge(*mpFat, std::max(-xv - *mpXat, 0.0));
    K.bt = edge(*mpFbt, std::max(xv - *mpXbt, 0.0));
    // The centre closes once |xv| exceeds p_c*x_vmax.
    addCentre(K, edge(*mpFc, std::max(xvmax - std::fabs(xv) / *mpPc, 0.0)));
    return K;
}

} // namespace tlmhub
