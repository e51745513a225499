#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated orifice with a check valve in parallel, Pp <-> Pc: flow from Pc to
// Pp passes the orifice area Ao, flow from Pp to Pc the back valve area Ab. The flow law
// blends laminar and turbulent flow; two Newton iterations per step.
class HydraulicOrificeCheckValveG : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPp = nullptr, *mpPc = nullptr;
    double *mpAo = nullptr, *mpDh = nullptr, *mpLo = nullptr;
    double *mpRho = nullptr, *mpVisc = nullptr, *mpCdt = nullptr, *mpDel = nullptr, *mpAb = nullptr,
           *mpDhb = nullptr;
    double *mpRo = nullptr, *mpDRL = nullptr, *mpCd = nullptr;
    double *mpPp_p = nullptr, *mpPp_q = nullptr, *mpPp_c = nullptr, *mpPp_Zc = nullptr;
    double *mpPc_p = nullptr, *mpPc_q = nullptr, *mpPc_c = nullptr, *mpPc_Zc = nullptr;

    // Newton state persisting between steps (generated-component convention).
    double qp = 0.0, pp = 0.0, pc = 0.0;

    Matrix mJ{3, 3};
    Vec mF{3}, mX{3};
    EquationSystemSolver mSolver{3};
};

} // namespace tlmhub
