#include "core/components/hydraulic/HydraulicPressureDropValve.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

double HydraulicPressureDropValve::openingPressure(double gamma, double c1, double c2, double pref) const
{
    // Open once the drop c1 - c2 exceeds p_ref.
    return gamma * (c1 - c2) - pref;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureDropValve, "Hydraulic")

} // namespace tlmhub
