#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated (Compgen) pressure-controlled variable pump, P1 (suction) -> P2
// (pressure), P3 = pressure-sensing port without flow. The regulator is linearised at
// pnom/speednom and rescaled to the current operating point:
//   dqp = s*(pdif + p3 - p2)*(1 + s/wp1e) / ((Lpe*s + Rpe)*(1 + tauv*s)),  der(qp) = dqp,
// with dqp in [dqmin, dqmax] and qp in [qmine, qmaxe]; q2 = qp - Kcp*(p2 - p1).
// Generated-component conventions as in docs/components/hydraulic-completion.md.
class HydraulicPressureControlledPumpG : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    // Operating-point rescaling of the linearised regulator (uses the member p2).
    void evaluateLocalExpressions();
    // Bilinear (Tustin) terms of the regulator and the integrator that depend only on
    // this step's values; the next steps subtract them.
    void evaluateDelayedParts(double& rD1, double& rD2, double& rDq) const;

    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    Port* mpP3 = nullptr;

    // Input variables (all re-read every step, as the generated code does).
    double* mpPdif = nullptr;
    double* mpSpeed = nullptr;
    double* mpRho = nullptr;
    double* mpQmin = nullptr;
    double* mpDp = nullptr;
    double* mpEpsmin = nullptr;
    double* mpLp = nullptr;
    double* mpRp = nullptr;
    double* mpWp1 = nullptr;
    double* mpKcp = nullptr;
    double* mpTauv = nullptr;
    double* mpTp = nullptr;
    double* mpTm = nullptr;
    double* mpPnom = nullptr;
    double* mpSpeednom = nullptr;
    // Output variables.
    double* mpQpOut = nullptr;
    double* mpDqpOut = nullptr;
    double* mpEpsOut = nullptr;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_dE = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_dE = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_p = nullptr, *mpP3_q = nullptr, *mpP3_dE = nullptr, *mpP3_c = nullptr;

    // Member state persisting between steps (generated-component convention).
    double pdif = 0, speed = 0, Dp = 0, epsmin = 0, Lp = 0, Rp = 0, wp1 = 0, Kcp = 0, tauv = 0;
    double Tp = 0, Tm = 0, pnom = 0, speednom = 0;
    double p1 = 0, q1 = 0, dE1 = 0, p2 = 0, q2 = 0, dE2 = 0, p3 = 0, q3 = 0, dE3 = 0;
    double qp = 0, dqp = 0, eps = 0;
    double qmine = 0, qmaxe = 0, dqmin = 0, dqmax = 0, Lpe = 0, Rpe = 0, wp1e = 0;

    // Delayed parts used by the next step: mD1 (one step old) and mD2 (two steps old) of
    // the regulator, mDq of the qp integrator. mD2Newest is the two-step term computed
    // at the end of the last step, which becomes mD2 one step later.
    double mD1 = 0, mD2 = 0, mD2Newest = 0, mDq = 0;

    Matrix mJ{5, 5};
    Vec mF{5}, mX{5};
    EquationSystemSolver mSolver{5};
};

} // namespace tlmhub
