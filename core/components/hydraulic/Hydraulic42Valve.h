#pragma once
#include "core/components/hydraulic/HydraulicFourWaySpoolValveBase.h"

namespace tlmhub {

// Q-type 4/2 valve with a closed rest position: P-A and B-T open together as the spool
// moves from 0 to x_vmax; P-B and A-T never open.
class Hydraulic42Valve : public HydraulicFourWaySpoolValveBase {
public:
    Hydraulic42Valve() : HydraulicFourWaySpoolValveBase({890.0, 1.0, false, false}) {}

protected:
    void addEdgeInputs() override;
    Edges edges(double xv, double xvmax) const override;

private:
    double *mpFpa = nullptr, *mpFbt = nullptr;
};

} // namespace tlmhub
