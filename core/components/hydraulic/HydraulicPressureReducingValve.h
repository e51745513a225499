#pragma once
#include "core/components/hydraulic/HydraulicPressureValveBase.h"

namespace tlmhub {

// Q-type pressure reducing valve P1 -> P2: the spool closes as the outlet
// pressure p2 rises towards p_ref (normally open).
class HydraulicPressureReducingValve : public HydraulicPressureValveBase {
protected:
    double openingPressure(double gamma, double c1, double c2, double pref) const override;
};

} // namespace tlmhub
