#include "core/components/hydraulic/Hydraulic33Valve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void Hydraulic33Valve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);

    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("in", "Desired spool position", "m", 0.0, &mpIn);
    addInputVariable("C_q", "Flow Coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool Diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("x_vmax", "Maximum Spool Displacement", "m", 0.01, &mpXvmax);
    addInputVariable("x_pa", "Spool Overlap From Port P To A", "m", -1e-6, &mpXpa);
    addInputVariable("x_at", "Spool Overlap From Port A To T", "m", -1e-6, &mpXat);
    addConstant("omega_h", "Resonance Frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping Factor", "-", 1.0, mDeltah);
}

void Hydraulic33Valve::initialize()
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
    const double y0 = limit(*mpXv, -xvmax, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, -xvmax, xvmax);
}

void Hydraulic33Valve::simulateOneTimestep()
{
    double cp = *mpPP_c, Zcp = *mpPP_Zc;
    double ct = *mpPT_c, Zct = *mpPT_Zc;
    double ca = *mpPA_c, Zca = *mpPA_Zc;
    const double xvmax = *mpXvmax;
    const double k = *mpCq * pi * *mpD * std::sqrt(2.0 / *mpRho);

    double xvin = *mpIn;
    limitValue(xvin, -xvmax, xvmax);
    mSpool.update(xvin);
    const double xv = mSpool.value();

    mQpa.setFlowCoefficient(k * *mpFpa * std::max(xv - *mpXpa, 0.0));
    mQat.setFlowCoefficient(k * *mpFat * std::max(-xv - *mpXat, 0.0));

    double qpa = mQpa.getFlow(cp, ca, Zcp, Zca);
    double qat = mQat.getFlow(ca, ct, Zca, Zct);
    double qp = -qpa, qt = qat, qa = qpa - qat;

    bool cav = false;
    if (ca + qa * Zca < 0.0) { ca = 0.0; Zca = 0.0; cav = true; }
    if (cp + qp * Zcp < 0.0) { cp = 0.0; Zcp = 0.0; cav = true; }
    if (ct + qt * Zct < 0.0) { ct = 0.0; Zct = 0.0; cav = true; }
    if (cav) {
        // As Hopsan: the retry routes only the edge on the spool's side (the
        // overlap leakage of the other edge is dropped).
        qpa = mQpa.getFlow(cp, ca, Zcp, Zca);
        qat = mQat.getFlow(ca, ct, Zca, Zct);
        if (xv >= 0.0) { qp = -qpa; qa = qpa; qt = 0.0; }
        else { qp = 0.0; qa = -qat; qt = qat; }
    }

    *mpPP_p = cp + qp * Zcp;
    *mpPP_q = qp;
    *mpPA_p = ca + qa * Zca;
    *mpPA_q = qa;
    *mpPT_p = ct + qt * Zct;
    *mpPT_q = qt;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic33Valve, "Hydraulic")

} // namespace tlmhub
