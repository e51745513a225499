#include "core/components/hydraulic/HydraulicPressureControlledPumpG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicPressureControlledPumpG::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Hydraulic);

    addInputVariable("pdif", "Reference pressure (set point of p2 - p3)", "Pa", 2.0e7, &mpPdif);
    addInputVariable("speed", "Pump speed", "rad/s", 157.0, &mpSpeed);
    addInputVariable("rho", "Oil density (not used by the equations)", "kg/m^3", 870.0, &mpRho);
    addInputVariable("qmin", "Minimum flow at nominal speed (not used by the equations)", "m^3/s", 0.0, &mpQmin);
    addInputVariable("Dp", "Maximum displacement per revolution", "m^3", 3.0e-4, &mpDp);
    addInputVariable("epsmin", "Minimum relative displacement", "-", 0.0, &mpEpsmin);
    addInputVariable("Lp", "Regulator inductance at pnom, speednom", "-", 1.83e10, &mpLp);
    addInputVariable("Rp", "Regulator resistance (droop) at pnom, speednom", "-", 1.68e10, &mpRp);
    addInputVariable("wp1", "Regulator break frequency at speednom", "rad/s", 13.3, &mpWp1);
    addInputVariable("Kcp", "Leakage coefficient P2 -> P1", "-", 1.0e-12, &mpKcp);
    addInputVariable("tauv", "Control valve time constant", "s", 0.05, &mpTauv);
    addInputVariable("Tp", "Time from minimum to full displacement at pnom", "s", 0.001, &mpTp);
    addInputVariable("Tm", "Time from full to minimum displacement at pnom", "s", 0.001, &mpTm);
    addInputVariable("pnom", "Nominal pressure of the linearisation", "Pa", 7.0e6, &mpPnom);
    addInputVariable("speednom", "Nominal speed of the linearisation", "rad/s", 157.0, &mpSpeednom);

    addOutputVariable("qp", "Pump flow", "m^3/s", 0.0, &mpQpOut);
    addOutputVariable("dqp", "Rate of change of the pump flow", "m^3/s^2", 0.0, &mpDqpOut);
    addOutputVariable("eps", "Relative displacement qp/qmaxe", "-", 0.0, &mpEpsOut);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "qmin"}, false);
}

void HydraulicPressureControlledPumpG::evaluateLocalExpressions()
{
    // 0.159155 is the generated code's literal for 1/(2*pi): rad/s -> rev/s.
    qmine = 0.159155 * Dp * epsmin * speed;
    qmaxe = 0.159155 * Dp * speed;
    // Stroking rates and regulator gains scale with sqrt(p2/pnom) and speed/speednom;
    // the speed is kept above 0.1 rad/s so the scaling never divides by zero.
    const double speede = lowLimit(speed, 0.1);
    dqmin = -(qmaxe - qmine) * std::sqrt(p2 / pnom) / Tm;
    dqmax = (qmaxe - qmine) * std::sqrt(p2 / pnom) / Tp;
    Lpe = Lp * std::sqrt(pnom / p2) * speednom / speede;
    Rpe = Rp * std::sqrt(pnom / p2) * speednom / speede;
    wp1e = wp1 * speede / speednom;
}

// Tustin form of dqp*(Lpe*s + Rpe)*(1 + tauv*s) = s*(1 + s/wp1e)*e, e = pdif + p3 - p2:
//   A0*dqp[n] = B0*e[n] + B1*e[n-1] + B2*e[n-2] - A1*dqp[n-1] - A2*dqp[n-2]
// with A0 = (2 Lpe + h Rpe)(h + 2 tauv), A1 = 2 h^2 Rpe - 8 Lpe tauv,
// A2 = (h Rpe - 2 Lpe)(h - 2 tauv), B = (2/wp1e)*(2 + h wp1e, -4, 2 - h wp1e).
// rD1 and rD2 are the parts that step n+1 and n+2 subtract; rDq is the one of the
// trapezoidal integrator qp[n+1] = qp[n] + h/2*(dqp[n+1] + dqp[n]).
void HydraulicPressureControlledPumpG::evaluateDelayedParts(double& rD1, double& rD2, double& rDq) const
{
    const double h = mTimestep;
    const double e = pdif + p3 - p2;
    const double wA0 = wp1e * (2.0 * Lpe + h * Rpe) * (h + 2.0 * tauv);
    const double A1 = 2.0 * h * h * Rpe - 8.0 * Lpe * tauv;
    const double A2 = (h * Rpe - 2.0 * Lpe) * (h - 2.0 * tauv);
    rD1 = (8.0 * e + wp1e * A1 * dqp) / wA0;
    rD2 = ((2.0 * h * wp1e - 4.0) * e + wp1e * A2 * dqp) / wA0;
    rDq = -(h * dqp + 2.0 * qp) / 2.0;
}

void HydraulicPressureControlledPumpG::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_dE = getSafeNodeDataPtr(mpP1, NodeHydraulic::HeatFlow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_dE = getSafeNodeDataPtr(mpP2, NodeHydraulic::HeatFlow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_p = getSafeNodeDataPtr(mpP3, NodeHydraulic::Pressure);
    mpP3_q = getSafeNodeDataPtr(mpP3, NodeHydraulic::Flow);
    mpP3_dE = getSafeNodeDataPtr(mpP3, NodeHydraulic::HeatFlow);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeHydraulic::WaveVariable);

    // Start values: node variables, inputs and the output start values.
    p1 = *mpP1_p; q1 = *mpP1_q; dE1 = *mpP1_dE;
    p2 = *mpP2_p; q2 = *mpP2_q; dE2 = *mpP2_dE;
    p3 = *mpP3_p; q3 = *mpP3_q; dE3 = *mpP3_dE;
    qp = *mpQpOut;
    dqp = *mpDqpOut;
    eps = *mpEpsOut;
    pdif = *mpPdif; speed = *mpSpeed; Dp = *mpDp; epsmin = *mpEpsmin; Lp = *mpLp; Rp = *mpRp;
    wp1 = *mpWp1; Kcp = *mpKcp; tauv = *mpTauv; Tp = *mpTp; Tm = *mpTm; pnom = *mpPnom;
    speednom = *mpSpeednom;

    // The regulator starts at rest at the start values: every delayed slot holds the
    // parts computed from them.
    evaluateLocalExpressions();
    evaluateDelayedParts(mD1, mD2, mDq);
    mD2Newest = mD2;

    // As the generated code, initialisation ends with one step.
    simulateOneTimestep();
}

void HydraulicPressureControlledPumpG::simulateOneTimestep()
{
    const double h = mTimestep;

    // Read the wave variables and every input.
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double c3 = *mpP3_c;
    pdif = *mpPdif; speed = *mpSpeed; Dp = *mpDp; epsmin = *mpEpsmin; Lp = *mpLp; Rp = *mpRp;
    wp1 = *mpWp1; Kcp = *mpKcp; tauv = *mpTauv; Tp = *mpTp; Tm = *mpTm; pnom = *mpPnom;
    speednom = *mpSpeednom;

    // Operating point from the previous step's p2.
    evaluateLocalExpressions();

    // Two damped Newton iterations on the unknowns [dqp, qp, q2, p1, p2], starting from
    // the previous step's values.
    mX[0] = dqp; mX[1] = qp; mX[2] = q2; mX[3] = p1; mX[4] = p2;
    const double B0 = 2.0 * (2.0 + h * wp1e) / ((2.0 * Lpe + h * Rpe) * (h + 2.0 * tauv) * wp1e);
    for (int iter = 1; iter <= 2; ++iter) {
        // p3 is the member value: the previous step's c3 in the first iteration.
        const double zDq = B0 * (pdif + p3 - p2) - mD1 - mD2;
        const double zQ = dqp * h / 2.0 - mDq;
        const double a1 = c1 + q1 * Zc1;
        const double a2 = c2 + q2 * Zc2;

        mF[0] = dqp - limit(zDq, dqmin, dqmax);
        mF[1] = qp - limit(zQ, qmine, qmaxe);
        mF[2] = Kcp * (p2 - p1) + q2 - qp;
        mF[3] = p1 - lowLimit(a1, 0.0);
        mF[4] = p2 - lowLimit(a2, 0.0);

        // q1 is not an unknown of the system, so row 3 has no q2 entry.
        mJ[0][0] = 1.0; mJ[0][1] = 0.0; mJ[0][2] = 0.0; mJ[0][3] = 0.0;
        mJ[0][4] = B0 * dxLimit(zDq, dqmin, dqmax);
        mJ[1][0] = -h * dxLimit(zQ, qmine, qmaxe) / 2.0;
        mJ[1][1] = 1.0; mJ[1][2] = 0.0; mJ[1][3] = 0.0; mJ[1][4] = 0.0;
        mJ[2][0] = 0.0; mJ[2][1] = -1.0; mJ[2][2] = 1.0; mJ[2][3] = -Kcp; mJ[2][4] = Kcp;
        mJ[3][0] = 0.0; mJ[3][1] = 0.0; mJ[3][2] = 0.0; mJ[3][3] = 1.0; mJ[3][4] = 0.0;
        mJ[4][0] = 0.0; mJ[4][1] = 0.0; mJ[4][2] = -Zc2 * dxLowLimit(a2, 0.0);
        mJ[4][3] = 0.0; mJ[4][4] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicPressureControlledPumpG: singular Jacobian");
        }
        dqp = mX[0]; qp = mX[1]; q2 = mX[2]; p1 = mX[3]; p2 = mX[4];
        q1 = -q2;
        p3 = c3;
        q3 = 0.0;
        eps = qp / qmaxe;
    }

    // Shift the delayed parts: the two-step term computed last step becomes due next step.
    double D1 = 0.0, D2 = 0.0, Dq = 0.0;
    evaluateDelayedParts(D1, D2, Dq);
    mD1 = D1;
    mD2 = mD2Newest;
    mD2Newest = D2;
    mDq = Dq;

    *mpP1_p = p1; *mpP1_q = q1; *mpP1_dE = dE1;
    *mpP2_p = p2; *mpP2_q = q2; *mpP2_dE = dE2;
    *mpP3_p = p3; *mpP3_q = q3; *mpP3_dE = dE3;
    *mpQpOut = qp;
    *mpDqpOut = dqp;
    *mpEpsOut = eps;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlledPumpG, "Hydraulic")

} // namespace tlmhub
