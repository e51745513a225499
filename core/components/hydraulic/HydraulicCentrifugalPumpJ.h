#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated centrifugal pump with a rotational shaft port and its own
// shaft inertia (speed is a state); 5 unknowns, two Newton iterations per step.
class HydraulicCentrifugalPumpJ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double delayedPart() const;

    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPmr1 = nullptr;
    double *mp_kl = nullptr, *mp_b = nullptr, *mp_d = nullptr, *mp_beta2 = nullptr, *mp_Ap = nullptr;
    double *mp_rho = nullptr, *mp_Kcp = nullptr, *mp_Bp = nullptr, *mp_Jp = nullptr;
    double *mp_q2e = nullptr, *mp_Pin = nullptr, *mp_Pout = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpPmr1_t = nullptr, *mpPmr1_a = nullptr, *mpPmr1_w = nullptr, *mpPmr1_c = nullptr,
           *mpPmr1_Zc = nullptr, *mpPmr1_Je = nullptr;

    double kl = 0, b = 0, d = 0, beta2 = 0, Ap = 0, rho = 0, Kcp = 0, Bp = 0, Jp = 0;
    double p1 = 0, q1 = 0, c1 = 0, Zc1 = 0, p2 = 0, q2 = 0, c2 = 0, Zc2 = 0;
    double tormr1 = 0, thetamr1 = 0, wmr1 = 0, cmr1 = 0, Zcmr1 = 0, eqInertiamr1 = 0;
    double q2e = 0, Pin = 0, Pout = 0;
    double mDprev = 0;

    Matrix mJ{5, 5};
    Vec mF{5}, mX{5};
    EquationSystemSolver mSolver{5};
};

} // namespace tlmhub
