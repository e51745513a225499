#include "core/components/hydraulic/Hydraulic33ShuttleValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void Hydraulic33ShuttleValve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);

    addOutputVariable("xv_out", "Spool position", "", 0.0, &mpXv);
    addInputVariable("C_q", "Flow Coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil Density", "kg/m^3", 890.0, &mpRho);
    addInputVariable("d", "Spool Diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("x_pa", "Spool Overlap From Port P To A", "m", -1e-6, &mpXpa);
    addInputVariable("x_at", "Spool Overlap From Port A To T", "m", -1e-6, &mpXat);
    addConstant("x_vmax", "Maximum Spool Displacement", "m", 0.01, mXvmax);
    addConstant("d_1", "Damp orifice 1 diam.", "m", 1.0e-3, mD1);
    addConstant("d_2", "Damp orifice 2 diam.", "m", 1.0e-3, mD2);
}

void Hydraulic33ShuttleValve::initialize()
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

    // As Hopsan, the start position also seeds the integrator's delayed input.
    const double x0 = limit(*mpXv, -mXvmax, mXvmax);
    mX.initialize(mTimestep, x0, x0, -mXvmax, mXvmax);

    // Damping orifices and spool area use the start values of C_q, rho, d.
    mK1 = *mpCq * pi * mD1 * mD1 / 4.0 * std::sqrt(2.0 / *mpRho);
    mK2 = *mpCq * pi * mD2 * mD2 / 4.0 * std::sqrt(2.0 / *mpRho);
    mA = pi * *mpD * *mpD / 4.0;
}

void Hydraulic33ShuttleValve::simulateOneTimestep()
{
    double cp = *mpPP_c, Zcp = *mpPP_Zc;
    double ct = *mpPT_c, Zct = *mpPT_Zc;
    double ca = *mpPA_c, Zca = *mpPA_Zc;

    // The two damping orifices in series between PP and PT (previous-step pressures):
    // the spool chamber sits at the pressure that passes equal flows through both.
    const double pP = *mpPP_p, pT = *mpPT_p;
    const double pSpool = (mK1 * mK1 * pP + mK2 * mK2 * pT) / (mK1 * mK1 + mK2 * mK2);
    const double v = sign(pP - pSpool) * mK1 * std::sqrt(std::fabs(pP - pSpool)) / mA;
    const double xv = mX.update(v);

    const double k = *mpCq * pi * *mpD * std::sqrt(2.0 / *mpRho);
    mQpa.setFlowCoefficient(k * *mpFpa * std::max(-xv - *mpXpa, 0.0));
    mQat.setFlowCoefficient(k * *mpFat * std::max(xv - *mpXat, 0.0));

    double qp = 0, qa = 0, qt = 0;
    auto solve = [&]() {
        const double qpa = mQpa.getFlow(cp, ca, Zcp, Zca);
        const double qat = mQat.getFlow(ca, ct, Zca, Zct);
        qp = -qpa;
        qa = qpa - qat;
        qt = qat;
    };
    solve();

    bool cav = false;
    if (ca + qa * Zca < 0.0) { ca = 0.0; Zca = 0.0; cav = true; }
    if (cp + qp * Zcp < 0.0) { cp = 0.0; Zcp = 0.0; cav = true; }
    if (ct + qt * Zct < 0.0) { ct = 0.0; Zct = 0.0; cav = true; }
    if (cav) { solve(); }

    *mpPP_p = cp + qp * Zcp;
    *mpPP_q = qp;
    *mpPA_p = ca + qa * Zca;
    *mpPA_q = qa;
    *mpPT_p = ct + qt * Zct;
    *mpPT_q = qt;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic33ShuttleValve, "Hydraulic")

} // namespace tlmhub
