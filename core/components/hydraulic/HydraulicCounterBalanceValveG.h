#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated counterbalance valve: restrictor P1 -> P2 opened by
// p1 - p2 + kappa*p3 against pref (P3 = pilot, no flow); Newton solved.
class HydraulicCounterBalanceValveG : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double delayedPart() const;

    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    Port* mpP3 = nullptr;
    double* mp_pref = nullptr;
    double* mp_rho = nullptr;
    double* mp_visc = nullptr;
    double* mp_Dv = nullptr;
    double* mp_frac = nullptr;
    double* mp_kappa = nullptr;
    double* mp_Bv = nullptr;
    double* mp_Xvmax = nullptr;
    double* mp_Cq = nullptr;
    double* mp_phi = nullptr;
    double* mp_ks = nullptr;
    double* mp_p0 = nullptr;
    double* mpXvOut = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_p = nullptr, *mpP3_q = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;

    // Member state persisting between steps (generated-component convention).
    double pref = 0, rho = 0, Dv = 0, frac = 0, kappa = 0, Bv = 0, Xvmax = 0, Cq = 0, phi = 0, ks = 0, p0 = 0;
    double xv = 0, p1 = 0, q1 = 0, c1 = 0, Zc1 = 0, p2 = 0, q2 = 0, c2 = 0, Zc2 = 0, p3 = 0, q3 = 0, c3 = 0, Zc3 = 0;
    double Av = 0, w = 0, cf = 0, D1 = 0;

    Matrix mJ{5, 5};
    Vec mF{5}, mX{5};
    EquationSystemSolver mSolver{5};
};

} // namespace tlmhub
