#include "core/components/hydraulic/HydraulicValvePlate.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicValvePlate::configure()
{
    addInputVariable("phi_P", "Length of grooves", "deg", 160.0, &mpPhiP);
    addInputVariable("phi_1", "Length of first pre-compression notch", "deg", 6.0, &mpPhi1);
    addInputVariable("phi_2", "Length of second pre-compression notch", "deg", 6.0, &mpPhi2);
    addInputVariable("Delta_alpha", "Length of rounded groove ends", "deg", 5.0, &mpDAlpha);
    addInputVariable("alpha_f", "Length of port opening", "deg", 30.0, &mpAlphaF);
    addInputVariable("R_f", "Radius to groove centre line", "m", 0.03, &mpRf);
    addInputVariable("theta_1", "Notch angle 1", "deg", 6.0, &mpTh1);
    addInputVariable("theta_2", "Notch angle 2", "deg", 90.0, &mpTh2);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("movement", "Shaft speed", "rad/s", 160.0, &mpMovement);
    addOutputVariable("DEBUG1", "Shaft angle", "", &mpDebug1);
    addOutputVariable("DEBUG2", "Opening area B of piston 0", "", &mpDebug2);
    addOutputVariable("DEBUG3", "Opening area A of piston 2", "", &mpDebug3);

    mpP1 = addPowerMultiPort("P1", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPB = addPowerPort("PB", NodeType::Hydraulic);
}

void HydraulicValvePlate::initialize()
{
    mN = getNumPorts(mpP1);
    mvpP1_p.assign(mN, nullptr);
    mvpP1_q.assign(mN, nullptr);
    mvpP1_c.assign(mN, nullptr);
    mvpP1_Zc.assign(mN, nullptr);
    mP1.assign(mN, 0.0);
    mQ1.assign(mN, 0.0);
    mC1.assign(mN, 0.0);
    mZc1.assign(mN, 0.0);
    mXva.assign(mN, 0.0);
    mXvb.assign(mN, 0.0);
    for (std::size_t i = 0; i < mN; ++i) {
        mvpP1_p[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::Pressure);
        mvpP1_q[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::Flow);
        mvpP1_c[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::WaveVariable);
        mvpP1_Zc[i] = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::CharImpedance);
    }
    mpPA_p = getSafeNodeDataPtr(mpPA, NodeHydraulic::Pressure);
    mpPA_q = getSafeNodeDataPtr(mpPA, NodeHydraulic::Flow);
    mpPA_c = getSafeNodeDataPtr(mpPA, NodeHydraulic::WaveVariable);
    mpPA_Zc = getSafeNodeDataPtr(mpPA, NodeHydraulic::CharImpedance);
    mpPB_p = getSafeNodeDataPtr(mpPB, NodeHydraulic::Pressure);
    mpPB_q = getSafeNodeDataPtr(mpPB, NodeHydraulic::Flow);
    mpPB_c = getSafeNodeDataPtr(mpPB, NodeHydraulic::WaveVariable);
    mpPB_Zc = getSafeNodeDataPtr(mpPB, NodeHydraulic::CharImpedance);

    if (mN < 3) {
        addWarningMessage("HydraulicValvePlate: DEBUG3 needs at least 3 pistons on P1; it stays 0");
    }

    mIntegrator.initialize(mTimestep, 0.0, 0.0);
}

// Opening area (m^2) of one piston towards one kidney as a function of the shaft
// angle x (deg); start is the angular offset of the piston (deg).
double HydraulicValvePlate::groove(double x, double start, double phi, double r, double R, double g1,
                                   double th11, double th21, double g2, double th12, double th22) const
{
    const double min_angle = 90.0 - phi / 2.0 - g1 - r;

    if (x < 0.0) {
        x = 360.0 - std::fmod(std::fabs(x) - start - min_angle, 360.0);
    } else {
        x = std::fmod(x - start - min_angle, 360.0);
    }

    // Angles to arc lengths on the groove radius.
    const double k = (1.0 / 360.0) * 2.0 * mRf * pi;
    x = x * k;
    phi = phi * k;
    g1 = g1 * k;
    g2 = g2 * k;
    r = r * k;
    R = R * k;
    th11 = th11 / 180.0 * pi;
    th21 = th21 / 180.0 * pi;
    th12 = th12 / 180.0 * pi;
    th22 = th22 / 180.0 * pi;

    const double T1 = std::tan(th11) * std::tan(th11) * std::tan(th21 / 2.0);
    const double w1 = 2.0 * g1 * std::tan(th11) * std::tan(th21 / 2.0);
    const double w2 = 2.0 * g2 * std::tan(th12) * std::tan(th22 / 2.0);
    const double k2 = r * r * pi / 2.0;
    const double k3 = g1 * g1 * T1;
    const double k5 = g2 * g2 * std::tan(th12) * std::tan(th12) * std::tan(th22 / 2.0);

    double ret = 0.0;
    if (x >= 0.0 && x <= g1) {
        ret = std::min(x * x / g1 * w1 / 2.0, x * x * T1);
    } else if (x >= g1 && x <= g1 + 2.0 * r) {
        const double d = 2.0 * r - x + g1;
        const double A = 2.0 * r * r * std::acos(d / (2.0 * r)) - 0.5 * d * std::sqrt(4.0 * r * r - d * d);
        ret = k3 + A;
    } else if (x >= g1 + 2.0 * r && x <= R) {
        ret = k3 + k2 + (x - g1 - 2.0 * r) * 2.0 * r + k2;
    } else if (x >= R && x <= R + g1) {
        const double e = g1 + R - x;
        ret = std::min(e * e / g1 * w1 / 2.0, e * e * T1) + k2 + (x - g1 - 2.0 * r) * 2.0 * r + k2;
    } else if (x >= R + g1 && x <= g1 + phi) {
        ret = k2 + (R - 2.0 * r) * 2.0 * r + k2;
    } else if (x >= g1 + phi && x <= g1 + phi + g2) {
        const double e = x - g1 - phi;
        // Divides by g1 and uses T1 also for the second notch (reference quirk).
        ret = k2 + (R - 2.0 * r + phi + g1 - x) * 2.0 * r + k2 + std::min(e * e / g1 * w2 / 2.0, e * e * T1);
    } else if (x >= g1 + phi + g2 && x <= g1 + phi + R - 2.0 * r) {
        ret = k2 + (R - 2.0 * r + phi + g1 - x) * 2.0 * r + k2 + k5;
    } else if (x >= g1 + phi + R - 2.0 * r && x <= g1 + phi + R) {
        const double d = x - g1 - phi - R + 2.0 * r;
        const double A = 2.0 * r * r * std::acos(d / (2.0 * r)) - 0.5 * d * std::sqrt(4.0 * r * r - d * d);
        ret = A + k5;
    } else if (x >= g1 + phi + R && x <= g1 + phi + R + g2) {
        const double e = R - x + g1 + phi + g2;
        ret = std::min(e * e / g1 * w2 / 2.0, e * e * T1);
    }
    return ret;
}

void HydraulicValvePlate::simulateOneTimestep()
{
    const double movement = *mpMovement;
    const double phiP = *mpPhiP, phi1 = *mpPhi1, phi2 = *mpPhi2, dAlpha = *mpDAlpha;
    const double alphaF = *mpAlphaF, th1 = *mpTh1, th2 = *mpTh2, rho = *mpRho;
    mRf = *mpRf;

    for (std::size_t i = 0; i < mN; ++i) {
        mC1[i] = *mvpP1_c[i];
        mZc1[i] = *mvpP1_Zc[i];
    }
    const double ca = *mpPA_c, Zca = *mpPA_Zc;
    const double cb = *mpPB_c, Zcb = *mpPB_Zc;

    const double a1 = mIntegrator.update(movement); // shaft angle (rad)

    for (std::size_t i = 0; i < mN; ++i) {
        const double start = static_cast<double>(i) * 360.0 / static_cast<double>(mN);
        const double start2 = start + 180.0;
        mXva[i] = groove(a1 * 180.0 / pi, start, phiP, dAlpha, alphaF, phi1, th1, th2, phi2, th1, th2);
        mXvb[i] = groove(a1 * 180.0 / pi, start2, phiP, dAlpha, alphaF, phi1, th1, th2, phi2, th1, th2);
    }

    *mpDebug1 = a1;
    if (mN > 0) { *mpDebug2 = mXvb[0]; }
    if (mN > 2) { *mpDebug3 = mXva[2]; }

    double qa = 0.0;
    double qb = 0.0;
    for (std::size_t i = 0; i < mN; ++i) {
        mQ1[i] = 0.0;
        mTurb.setFlowCoefficient(0.67 * mXva[i] * std::sqrt(2.0 / rho));
        const double q1a = mTurb.getFlow(mC1[i], ca, mZc1[i], Zca);
        mQ1[i] -= q1a;
        qa += q1a;
    }
    for (std::size_t i = 0; i < mN; ++i) {
        mTurb.setFlowCoefficient(0.67 * mXvb[i] * std::sqrt(2.0 / rho));
        const double q1b = mTurb.getFlow(mC1[i], cb, mZc1[i], Zcb);
        mQ1[i] -= q1b;
        qb += q1b;
        mP1[i] = mC1[i] + mQ1[i] * mZc1[i];
    }

    const double pa = ca + qa * Zca;
    const double pb = cb + qb * Zcb;

    for (std::size_t i = 0; i < mN; ++i) {
        *mvpP1_p[i] = mP1[i];
        *mvpP1_q[i] = mQ1[i];
    }
    *mpPA_p = pa;
    *mpPA_q = qa;
    *mpPB_p = pb;
    *mpPB_q = qb;
}

TLMHUB_REGISTER_COMPONENT(HydraulicValvePlate, "Hydraulic")

} // namespace tlmhub
