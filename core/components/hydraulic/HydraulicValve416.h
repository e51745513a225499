#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated 4/3 valve with four independently controlled edges (P-A, A-T,
// P-B, B-T); flows solved by two Newton iterations per step.
class HydraulicValve416 : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void localExpressions();

    Port* mpPp = nullptr;
    Port* mpPt = nullptr;
    Port* mpPa = nullptr;
    Port* mpPb = nullptr;
    double* mp_xvpa = nullptr;
    double* mp_xvta = nullptr;
    double* mp_xvpb = nullptr;
    double* mp_xvtb = nullptr;
    double* mp_rho = nullptr;
    double* mp_Cq = nullptr;
    double* mp_Sd = nullptr;
    double* mp_Frpa = nullptr;
    double* mp_Frta = nullptr;
    double* mp_Frpb = nullptr;
    double* mp_Frtb = nullptr;
    double* mp_Xpa0 = nullptr;
    double* mp_Xta0 = nullptr;
    double* mp_Xpb0 = nullptr;
    double* mp_Xtb0 = nullptr;
    double* mp_Xvmax = nullptr;
    double* mp_plam = nullptr;
    double *mpPp_p = nullptr, *mpPp_q = nullptr, *mpPp_c = nullptr, *mpPp_Zc = nullptr;
    double *mpPt_p = nullptr, *mpPt_q = nullptr, *mpPt_c = nullptr, *mpPt_Zc = nullptr;
    double *mpPa_p = nullptr, *mpPa_q = nullptr, *mpPa_c = nullptr, *mpPa_Zc = nullptr;
    double *mpPb_p = nullptr, *mpPb_q = nullptr, *mpPb_c = nullptr, *mpPb_Zc = nullptr;

    // Member state persisting between steps (generated-component convention).
    double xvpa = 0, xvta = 0, xvpb = 0, xvtb = 0, rho = 0, Cq = 0, Sd = 0, Frpa = 0, Frta = 0, Frpb = 0, Frtb = 0, Xpa0 = 0, Xta0 = 0, Xpb0 = 0, Xtb0 = 0, Xvmax = 0, plam = 0;
    double pp = 0, qp = 0, cp = 0, Zcp = 0, pt = 0, qt = 0, ct = 0, Zct = 0, pa = 0, qa = 0, ca = 0, Zca = 0, pb = 0, qb = 0, cb = 0, Zcb = 0;
    double Ks = 0, Kspa = 0, Ksta = 0, Kspb = 0, Kstb = 0;

    Matrix mJ{8, 8};
    Vec mF{8}, mX{8};
    EquationSystemSolver mSolver{8};
};

} // namespace tlmhub
