#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated 3/3 pressure control valve: P1 supply, P2 tank, P3 controlled
// outlet, P4 pilot (no flow); spool driven by pref - p4; Newton solved.
class HydraulicPressureControlValve33 : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void localExpressions();

    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    Port* mpP3 = nullptr;
    Port* mpP4 = nullptr;
    double* mp_pref = nullptr;
    double* mp_rho = nullptr;
    double* mp_Cq = nullptr;
    double* mp_Sd = nullptr;
    double* mp_Frap = nullptr;
    double* mp_Frat = nullptr;
    double* mp_Xap0 = nullptr;
    double* mp_Xat0 = nullptr;
    double* mp_plam = nullptr;
    double* mp_Bv = nullptr;
    double* mp_Xvmin = nullptr;
    double* mp_Xvmax = nullptr;
    double* mp_phi = nullptr;
    double* mp_ks = nullptr;
    double* mp_xv = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_p = nullptr, *mpP3_q = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;
    double *mpP4_p = nullptr, *mpP4_q = nullptr, *mpP4_c = nullptr, *mpP4_Zc = nullptr;

    // Member state persisting between steps (generated-component convention).
    double pref = 0, rho = 0, Cq = 0, Sd = 0, Frap = 0, Frat = 0, Xap0 = 0, Xat0 = 0, plam = 0, Bv = 0, Xvmin = 0, Xvmax = 0, phi = 0, ks = 0;
    double p1 = 0, q1 = 0, c1 = 0, Zc1 = 0, p2 = 0, q2 = 0, c2 = 0, Zc2 = 0, p3 = 0, q3 = 0, c3 = 0, Zc3 = 0, p4 = 0, q4 = 0, c4 = 0, Zc4 = 0;
    double xv = 0;
    double Ks = 0, Av = 0, cf = 0, D1 = 0;
    double delayedPart() const;

    Matrix mJ{7, 7};
    Vec mF{7}, mX{7};
    EquationSystemSolver mSolver{7};
};

} // namespace tlmhub
