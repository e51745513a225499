#pragma once
#include "core/components/hydraulic/HydraulicNeutralOpen43ValveBase.h"

namespace tlmhub {

// Q-type 4/3 valve whose centre position connects the supply P to the tank T
// (A and B blocked).
class Hydraulic43ValveNeutralSupplyToTank : public HydraulicNeutralOpen43ValveBase {
public:
    Hydraulic43ValveNeutralSupplyToTank() : HydraulicNeutralOpen43ValveBase({890.0, 1.0, true, true}) {}

protected:
    void addCentre(Edges& K, double Kc) const override;
};

} // namespace tlmhub
