#pragma once
#include "core/components/hydraulic/HydraulicPressureValveBase.h"

namespace tlmhub {

// Q-type pressure drop valve P1 -> P2: opens when the pressure difference
// p1 - p2 exceeds p_ref, so it keeps a drop of about p_ref across itself.
class HydraulicPressureDropValve : public HydraulicPressureValveBase {
protected:
    double openingPressure(double gamma, double c1, double c2, double pref) const override;
};

} // namespace tlmhub
