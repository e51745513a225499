#pragma once
#include "core/components/hydraulic/HydraulicNeutralOpen43ValveBase.h"

namespace tlmhub {

// Q-type 4/3 valve whose centre position connects A and B to the tank T (P blocked);
// the centre opening adds to the A-T and B-T edges.
class Hydraulic43ValveNeutralToTank : public HydraulicNeutralOpen43ValveBase {
public:
    Hydraulic43ValveNeutralToTank() : HydraulicNeutralOpen43ValveBase({890.0, 10.0, true, true}) {}

protected:
    void addCentre(Edges& K, double Kc) const override;
};

} // namespace tlmhub
