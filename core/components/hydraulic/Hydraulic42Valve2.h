#pragma once
#include "core/components/hydraulic/HydraulicFourWaySpoolValveBase.h"

namespace tlmhub {

// Q-type 4/2 valve without a closed position: at xv = 0 P-B and A-T are fully open, at
// xv = x_vmax P-A and B-T; in between both pairs are partly open.
class Hydraulic42Valve2 : public HydraulicFourWaySpoolValveBase {
public:
    Hydraulic42Valve2() : HydraulicFourWaySpoolValveBase({870.0, 1.0, false, true}) {}

protected:
    void addEdgeInputs() override;
    Edges edges(double xv, double xvmax) const override;

private:
    double *mpFpa = nullptr, *mpFpb = nullptr, *mpFat = nullptr, *mpFbt = nullptr;
};

} // namespace tlmhub
