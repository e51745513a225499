#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated centrifugal pump driven by a prescribed shaft speed; a
// 4-unknown nonlinear system is solved by two Newton iterations per step.
class HydraulicCentrifugalPump : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mp_omegap = nullptr, *mp_kl = nullptr, *mp_b = nullptr, *mp_d = nullptr, *mp_beta2 = nullptr;
    double *mp_Ap = nullptr, *mp_rho = nullptr, *mp_Kcp = nullptr, *mp_Bp = nullptr;
    double *mp_q2e = nullptr, *mp_torp = nullptr, *mp_Pin = nullptr, *mp_Pout = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;

    double p1 = 0, q1 = 0, c1 = 0, Zc1 = 0, p2 = 0, q2 = 0, c2 = 0, Zc2 = 0;
    double q2e = 0, torp = 0, Pin = 0, Pout = 0;

    Matrix mJ{4, 4};
    Vec mF{4}, mX{4};
    EquationSystemSolver mSolver{4};
};

} // namespace tlmhub
