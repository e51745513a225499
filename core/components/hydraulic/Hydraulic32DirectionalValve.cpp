#include "core/components/hydraulic/Hydraulic32DirectionalValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void Hydraulic32DirectionalValve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);

    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("in", "Open (> 0.5) or closed", "-", 0.0, &mpIn);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f", "Fraction of spool circumference that is opening", "-", 1.0, &mpF);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);
    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
}

void Hydraulic32DirectionalValve::initialize()
{
    mpPP_p = getSafeNodeDataPtr(mpPP, NodeHydraulic::Pressure);
    mpPP_q = getSafeNodeDataPtr(mpPP, NodeHydraulic::Flow);
    mpPP_c = getSafeNodeDataPtr(mpPP, NodeHydraulic::WaveVariable);
    mpPP_Zc = getSafeNodeDataPtr(mpPP, NodeHydraulic::CharImpedance);
    mpPT_p = getSafeNodeDataPtr(mpPT, NodeHydraulic::Pressure);
    mpPT_q = getSafeNodeDataPtr(mpPT, NodeHydraulic::Flow);
    mpPT_c = getSafeNodeDataPtr(mpPT, NodeHydraulic::WaveVariable);
    mpPT_Zc = getSafeNodeDataPtr(mpPT, NodeHydraulic::CharImpedance);
    mpPA_p = getSafeNodeDataPtr(mpPA, NodeHydraulic::Pressure);
    mpPA_q = getSafeNodeDataPtr(mpPA, NodeHydraulic::Flow);
    mpPA_c = getSafeNodeDataPtr(mpPA, NodeHydraulic::WaveVariable);
    mpPA_Zc = getSafeNodeDataPtr(mpPA, NodeHydraulic::CharImpedance);

    const double xvmax = *mpXvmax;
    const double y0 = limit(*mpXv, 0.0, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, 0.0, xvmax);
}

void Hydraulic32DirectionalValve::simulateOneTimestep()
{
    double cp = *mpPP_c, Zcp = *mpPP_Zc;
    double ct = *mpPT_c, Zct = *mpPT_Zc;
    double ca = *mpPA_c, Zca = *mpPA_Zc;
    const double rho = *mpRho, xvmax = *mpXvmax, Cq = *mpCq, d = *mpD, f = *mpF;

    if (doubleToBool(*mpIn)) { mSpool.update(xvmax); }
    else { mSpool.update(0.0); }
    const double xv = mSpool.value();

    const double xpanom = std::max(xv, 0.0);
    const double xatnom = std::max(xvmax - xv, 0.0);
    mQpa.setFlowCoefficient(Cq * f * pi * d * xpanom * std::sqrt(2.0 / rho));
    mQat.setFlowCoefficient(Cq * f * pi * d * xatnom * std::sqrt(2.0 / rho));

    double qp, qa, qt, pp, pa, pt;
    auto solve = [&]() {
        const double qpa = mQpa.getFlow(cp, ca, Zcp, Zca);
        const double qat = mQat.getFlow(ca, ct, Zca, Zct);
        qp = -qpa;
        qa = qpa - qat;
        qt = qat;
        pp = cp + qp * Zcp;
        pa = ca + qa * Zca;
        pt = ct + qt * Zct;
    };
    solve();

    bool cav = false;
    if (pa < 0.0) { ca = 0.0; Zca = 0.0; cav = true; }
    if (pp < 0.0) { cp = 0.0; Zcp = 0.0; cav = true; }
    if (pt < 0.0) { ct = 0.0; Zct = 0.0; cav = true; }
    if (cav) { solve(); }

    *mpPP_p = pp;
    *mpPP_q = qp;
    *mpPA_p = pa;
    *mpPA_q = qa;
    *mpPT_p = pt;
    *mpPT_q = qt;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic32DirectionalValve, "Hydraulic")

} // namespace tlmhub
