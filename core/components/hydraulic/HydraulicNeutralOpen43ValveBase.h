#pragma once
#include "core/components/hydraulic/HydraulicFourWaySpoolValveBase.h"

namespace tlmhub {

// Common part of the 4/3 valves whose centre position is open: the four overlapped
// edges of Hydraulic43Valve plus a centre opening x_c = max(x_vmax - |xv|/p_c, 0) over
// the fraction f_c of the circumference. The subclass routes the centre flow.
class HydraulicNeutralOpen43ValveBase : public HydraulicFourWaySpoolValveBase {
protected:
    using HydraulicFourWaySpoolValveBase::HydraulicFourWaySpoolValveBase;

    void addEdgeInputs() override;
    Edges edges(double xv, double xvmax) const override;
    virtual void addCentre(Edges& K, double Kc) const = 0;

private:
    double *mpPc = nullptr, *mpFc = nullptr;
    double *mpFpa = nullptr, *mpFpb = nullptr, *mpFat = nullptr, *mpFbt = nullptr;
    double *mpXpa = nullptr, *mpXpb = nullptr, *mpXat = nullptr, *mpXbt = nullptr;
};

} // namespace tlmhub
