#include "core/components/hydraulic/Hydraulic22Valve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void Hydraulic22Valve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);

    addInputVariable("in", "Desired spool position", "m", 0.0, &mpIn);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f", "Fraction of spool circumference that is opening", "-", 1.0, &mpF);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);
    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
}

void Hydraulic22Valve::initialize()
{
    mpPP_p = getSafeNodeDataPtr(mpPP, NodeHydraulic::Pressure);
    mpPP_q = getSafeNodeDataPtr(mpPP, NodeHydraulic::Flow);
    mpPP_c = getSafeNodeDataPtr(mpPP, NodeHydraulic::WaveVariable);
    mpPP_Zc = getSafeNodeDataPtr(mpPP, NodeHydraulic::CharImpedance);
    mpPA_p = getSafeNodeDataPtr(mpPA, NodeHydraulic::Pressure);
    mpPA_q = getSafeNodeDataPtr(mpPA, NodeHydraulic::Flow);
    mpPA_c = getSafeNodeDataPtr(mpPA, NodeHydraulic::WaveVariable);
    mpPA_Zc = getSafeNodeDataPtr(mpPA, NodeHydraulic::CharImpedance);

    const double xvmax = *mpXvmax;
    const double y0 = limit(*mpXv, 0.0, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, 0.0, xvmax);

    simulateOneTimestep();
}

void Hydraulic22Valve::simulateOneTimestep()
{
    double cp = *mpPP_c, Zcp = *mpPP_Zc;
    double ca = *mpPA_c, Zca = *mpPA_Zc;
    double xvin = *mpIn;
    const double Cq = *mpCq, rho = *mpRho, d = *mpD, f = *mpF, xvmax = *mpXvmax;

    limitValue(xvin, 0.0, xvmax);
    mSpool.update(xvin);
    const double xv = mSpool.value();

    // No max(xv, 0): the filter limits keep the opening non-negative.
    mTurb.setFlowCoefficient(Cq * f * pi * d * xv * std::sqrt(2.0 / rho));
    double qpa = mTurb.getFlow(cp, ca, Zcp, Zca);
    double qp = -qpa, qa = qpa;
    double pp = cp + qp * Zcp, pa = ca + qa * Zca;

    bool cav = false;
    if (pa < 0.0) { ca = 0.0; Zca = 0.0; cav = true; }
    if (pp < 0.0) { cp = 0.0; Zcp = 0.0; cav = true; }
    if (cav) {
        qpa = mTurb.getFlow(cp, ca, Zcp, Zca);
        if (xv >= 0.0) {
            qp = -qpa;
            qa = qpa;
        } else {
            qp = 0.0;
            qa = 0.0;
        }
        pp = cp + qp * Zcp;
        pa = ca + qa * Zca;
    }

    *mpPP_p = pp;
    *mpPP_q = qp;
    *mpPA_p = pa;
    *mpPA_q = qa;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic22Valve, "Hydraulic")

} // namespace tlmhub
