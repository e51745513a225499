#include "core/components/hydraulic/HydraulicPressureControlledPump.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void HydraulicPressureControlledPump::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPREF = addPowerPort("PREF", NodeType::Hydraulic, false);

    addOutputVariable("eps", "Relative displacement", "-", 1.0, &mpEps);
    addOutputVariable("a", "Angle", "rad", 0.0, &mpA);
    addInputVariable("p_dif", "Reference pressure difference", "Pa", 1.0e6, &mpPdif);
    addInputVariable("omega_p", "Pump speed", "rad/s", 125.0, &mpOmegap);
    addInputVariable("q_max", "Maximum flow at 125 rad/s", "m^3/s", 0.00125, &mpQmax);
    addInputVariable("l_p", "Regulator inductance at nominal pressure", "-", 7.0e7, &mpLp);
    addInputVariable("r_p", "Static characteristic at nominal pressure", "-", 1.0e9, &mpRp);
    addInputVariable("omega_p1", "Regulator lead frequency", "rad/s", 200.0, &mpOmegap1);
    addInputVariable("C_lp", "Leakage coefficient", "m^3/(s Pa)", 1.0e-12, &mpClp);
    addInputVariable("tao_v", "Control valve time constant", "s", 0.001, &mpTaov);
    addInputVariable("t_p", "Time from minimum to full displacement", "s", 0.15, &mpTp);
    addInputVariable("t_m", "Time from full to minimum displacement", "s", 0.12, &mpTm);
    addConstant("q_min", "Minimum flow at 125 rad/s", "m^3/s", 0.0, mQmin);
}

void HydraulicPressureControlledPump::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_p = getSafeNodeDataPtr(mpPREF, NodeHydraulic::Pressure);
    mpP3_q = getSafeNodeDataPtr(mpPREF, NodeHydraulic::Flow);
    mpP3_c = getSafeNodeDataPtr(mpPREF, NodeHydraulic::WaveVariable);

    const double p1 = *mpP1_p, c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double p2 = *mpP2_p;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double c3 = *mpP3_c;
    const double pdif = *mpPdif, omegap = *mpOmegap, qmax = *mpQmax, lp = *mpLp, rp = *mpRp;
    const double omegap1 = *mpOmegap1, Clp = *mpClp, taov = *mpTaov;

    const double q2 = qmax * (*mpEps) * (omegap / mMovementNom);
    const double gamma = 1.0 / (Clp * (Zc1 + Zc2) + 1.0);
    if (p2 < 1.0) { p2 = 1.0; }
    const double lpe = lp * std::sqrt(mPnom / p2) * (mMovementNom / (omegap + 0.001));
    const double y0 = q2 * (lpe + rp * taov + Zc2 * gamma / omegap1);

    *mpP1_p = p1;
    *mpP2_p = p2;

    const double c2e = (Clp * Zc1 + 1.0) * gamma * c2 + Clp * Zc2 * gamma * c1;
    const double u = pdif - c2e + c3;

    mYd = y0;
    mUd = u;
    mY1 = y0;
    mU1 = u;
    mVd = 0.0;
    *mpA = 0.0;
    *mpP2_q = q2;
}

// Discrete second-order regulator with rate limits (vmin, vmax) and output
// limits (ymin, ymax).
double HydraulicPressureControlledPump::fltppu(double u, double w01, double g1, double g2, double ymin,
                                               double ymax, double vmin, double vmax)
{
    const double h = mTimestep;
    mY2 = mY1;
    mY1 = mYd;
    mU2 = mU1;
    mU1 = mUd;

    const double ws = 1.0 / h;
    const double alf2 = g1 * 4.0 * ws * ws;
    const double alf1 = 2.0 / (w01 * h);
    const double g = g2 + alf2 + ws * 2.0;
    const double a1 = (g2 - alf2) * 2.0 / g;
    const double a2 = (g2 + alf2 - ws * 2.0) / g;
    const double b1 = (alf1 + 1.0) / g;
    const double b2 = 2.0 / g;
    const double b3 = (1.0 - alf1) / g;

    double y = -a1 * mY1 - a2 * mY2 + b1 * u + b2 * mU1 + b3 * mU2;
    double v = (y - mY1) / h;
    if (v > vmax) {
        y = mY1 + vmax * h;
        v = vmax;
    } else if (v <= vmin) {
        y = mY1 + vmin * h;
        v = vmin;
    }
    if (y > ymax) {
        y = ymax;
        v = 0.0;
    } else if (y < ymin) {
        y = ymin;
        v = 0.0;
    }
    mUd = u;
    mYd = y;
    mVd = v;
    return y;
}

void HydraulicPressureControlledPump::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double p2 = *mpP2_p;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    double c3 = *mpP3_c;
    const double pdif = *mpPdif, omegap = *mpOmegap, qmax = *mpQmax, lp = *mpLp, rp = *mpRp;
    const double omegap1 = *mpOmegap1, Clp = *mpClp, taov = *mpTaov, tp = *mpTp, tm = *mpTm;

    const double qmaxl = qmax * (omegap / mMovementNom);
    const double qminl = mQmin * (omegap / mMovementNom);

    if (p2 < 1.0) { p2 = 1.0; }
    const double lpe = lp * std::sqrt(mPnom / p2) * (mMovementNom / (omegap + 0.001));

    if (c3 < 0.0) { c3 = 0.0; }

    const double gamma = 1.0 / (Clp * (Zc1 + Zc2) + 1.0);
    const double c1e = (Clp * Zc2 + 1.0) * gamma * c1 + Clp * Zc1 * gamma * c2;
    const double c2e = (Clp * Zc1 + 1.0) * gamma * c2 + Clp * Zc2 * gamma * c1;

    const double denom = lpe + rp * taov + Zc2 * gamma / omegap1;
    const double g1 = lpe * taov / denom;
    const double g2 = (rp + Zc2 * gamma) / denom;
    const double u = pdif - c2e + c3;

    const double ymax = qmaxl * denom;
    const double ymin = qminl * denom;
    const double vmax = qmaxl * denom * std::sqrt(std::fabs(p2 - 1e5) / (mPnom * tp));
    const double vmin = -qmaxl * denom * std::sqrt(std::fabs(p2 - 1e5) / (mPnom * tm));

    double qp = fltppu(u, omegap1, g1, g2, ymin, ymax, vmin, vmax) / denom;
    // Zero-impedance ports give infinite/NaN bounds which fmin/fmax ignore.
    qp = std::fmin(std::fmax(qp, -c2 / Zc2), c1 / Zc1);

    const double p1 = c1e - Zc1 * gamma * qp;
    p2 = c2e + Zc2 * gamma * qp;
    const double ql = Clp * (p2 - p1);
    const double q2 = qp - ql;
    const double q1 = -q2;

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP3_p = c3;
    *mpP3_q = 0.0;
    *mpEps = q2 / qmaxl;
    *mpA = *mpA + omegap * mTimestep;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlledPump, "Hydraulic")

} // namespace tlmhub
