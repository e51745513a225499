#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated 3/3 spool valve (P, T, A); spool position given by the input
// xv (no spool dynamics); flows solved by two Newton iterations per step.
class HydraulicValve33 : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void localExpressions();

    Port* mpPp = nullptr;
    Port* mpPt = nullptr;
    Port* mpPa = nullptr;
    double* mp_xv = nullptr;
    double* mp_rho = nullptr;
    double* mp_Cq = nullptr;
    double* mp_Sd = nullptr;
    double* mp_Frap = nullptr;
    double* mp_Frat = nullptr;
    double* mp_Xap0 = nullptr;
    double* mp_Xat0 = nullptr;
    double* mp_Xvmax = nullptr;
    double* mp_plam = nullptr;
    double *mpPp_p = nullptr, *mpPp_q = nullptr, *mpPp_c = nullptr, *mpPp_Zc = nullptr;
    double *mpPt_p = nullptr, *mpPt_q = nullptr, *mpPt_c = nullptr, *mpPt_Zc = nullptr;
    double *mpPa_p = nullptr, *mpPa_q = nullptr, *mpPa_c = nullptr, *mpPa_Zc = nullptr;

    // Member state persisting between steps (generated-component convention).
    double xv = 0, rho = 0, Cq = 0, Sd = 0, Frap = 0, Frat = 0, Xap0 = 0, Xat0 = 0, Xvmax = 0, plam = 0;
    double pp = 0, qp = 0, cp = 0, Zcp = 0, pt = 0, qt = 0, ct = 0, Zct = 0, pa = 0, qa = 0, ca = 0, Zca = 0;
    double Ks = 0, Kspa = 0, Ksta = 0;

    Matrix mJ{6, 6};
    Vec mF{6}, mX{6};
    EquationSystemSolver mSolver{6};
};

} // namespace tlmhub
