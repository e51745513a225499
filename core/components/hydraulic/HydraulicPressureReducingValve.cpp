#include "core/components/hydraulic/HydraulicPressureReducingValve.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

double HydraulicPressureReducingValve::openingPressure(double gamma, double /*c1*/, double c2, double pref) const
{
    // Open while the outlet wave c2 is below p_ref.
    return gamma * (-c2) + pref;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureReducingValve, "Hydraulic")

} // namespace tlmhub
