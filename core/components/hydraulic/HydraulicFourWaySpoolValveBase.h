#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Shared body of Hopsan's directional 4-port spool valves (4/2 and 4/3 with an open
// centre): ports PP, PT, PA, PB, a second-order spool following `in`, and up to five
// turbulent metering edges P-A, P-B, A-T, B-T, P-T. A subclass adds its own inputs and
// says how wide each edge is open for a spool position.
class HydraulicFourWaySpoolValveBase : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

protected:
    struct Defaults {
        double rho = 890.0;
        double deltah = 1.0;
        bool negativeDemand = true; // `in` limited to [-x_vmax, x_vmax], else [0, x_vmax]
        bool negativeSpool = true;  // spool filter limited likewise
    };
    explicit HydraulicFourWaySpoolValveBase(Defaults defaults) : mDefaults(defaults) {}

    // Flow coefficients (m^3/(s sqrt(Pa))) of the five edges.
    struct Edges {
        double pa = 0.0, pb = 0.0, at = 0.0, bt = 0.0, pt = 0.0;
    };
    virtual void addEdgeInputs() = 0;
    virtual Edges edges(double xv, double xvmax) const = 0;

    // Orifice coefficient of an edge opened x over a fraction f of the spool circumference.
    double edge(double f, double x) const;

private:
    Defaults mDefaults;
    Port *mpPP = nullptr, *mpPT = nullptr, *mpPA = nullptr, *mpPB = nullptr;
    double *mpIn = nullptr, *mpXv = nullptr;
    double *mpCq = nullptr, *mpRho = nullptr, *mpD = nullptr, *mpXvmax = nullptr;
    double mOmegah = 100.0, mDeltah = 1.0;

    double *mpPP_p = nullptr, *mpPP_q = nullptr, *mpPP_c = nullptr, *mpPP_Zc = nullptr;
    double *mpPT_p = nullptr, *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    double *mpPB_p = nullptr, *mpPB_q = nullptr, *mpPB_c = nullptr, *mpPB_Zc = nullptr;

    SecondOrderTransferFunction mSpool;
    TurbulentFlowFunction mQpa, mQpb, mQat, mQbt, mQpt;
};

} // namespace tlmhub
