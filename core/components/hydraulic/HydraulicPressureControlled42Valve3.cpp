#include "core/components/hydraulic/HydraulicPressureControlled42Valve3.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicPressureControlled42Valve3::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPB = addPowerPort("PB", NodeType::Hydraulic);
    mpPC = addPowerPort("PC", NodeType::Hydraulic);

    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
    addInputVariable("Fs_min", "Pilot pressure where the spool starts to move", "Pa", 1e5, &mpFsmin);
    addInputVariable("Fs_max", "Pilot pressure for full spool stroke", "Pa", 1e6, &mpFsmax);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpfpa);
    addInputVariable("f_pb", "Fraction of spool circumference that is opening P-B", "-", 1.0, &mpfpb);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpfbt);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpfat);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);
    addOutputVariable("x_v", "Spool position", "m", 0.0, &mpXv);
}

void HydraulicPressureControlled42Valve3::initialize()
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
    mpPB_p = getSafeNodeDataPtr(mpPB, NodeHydraulic::Pressure);
    mpPB_q = getSafeNodeDataPtr(mpPB, NodeHydraulic::Flow);
    mpPB_c = getSafeNodeDataPtr(mpPB, NodeHydraulic::WaveVariable);
    mpPB_Zc = getSafeNodeDataPtr(mpPB, NodeHydraulic::CharImpedance);
    mpPC_p = getSafeNodeDataPtr(mpPC, NodeHydraulic::Pressure);
    mpPC_q = getSafeNodeDataPtr(mpPC, NodeHydraulic::Flow);
    mpPC_c = getSafeNodeDataPtr(mpPC, NodeHydraulic::WaveVariable);
    mpPC_Zc = getSafeNodeDataPtr(mpPC, NodeHydraulic::CharImpedance);

    // The spool always starts at 0 (the x_v start value is not used).
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, 0.0, 0.0, 0.0, *mpXvmax);
}

void HydraulicPressureControlled42Valve3::simulateOneTimestep()
{
    double cp = *mpPP_c, Zcp = *mpPP_Zc;
    double ct = *mpPT_c, Zct = *mpPT_Zc;
    double ca = *mpPA_c, Zca = *mpPA_Zc;
    double cb = *mpPB_c, Zcb = *mpPB_Zc;
    const double cc = *mpPC_c; // pilot wave variable
    const double Fs_min = *mpFsmin, Fs_max = *mpFsmax, Cq = *mpCq, rho = *mpRho, d = *mpD;
    const double f_pa = *mpfpa, f_pb = *mpfpb, f_bt = *mpfbt, f_at = *mpfat;
    const double xvmax = *mpXvmax;

    mSpool.update(std::min(1.0, std::max(0.0, (cc - Fs_min) / (Fs_max - Fs_min))) * xvmax);
    const double xv = mSpool.value();
    const double xpanom = xvmax - xv;
    const double xpbnom = xv;
    const double xatnom = xv;
    const double xbtnom = xvmax - xv;

    mQpa.setFlowCoefficient(Cq * f_pa * pi * d * xpanom * std::sqrt(2.0 / rho));
    mQbt.setFlowCoefficient(Cq * f_bt * pi * d * xbtnom * std::sqrt(2.0 / rho));
    mQpb.setFlowCoefficient(Cq * f_pb * pi * d * xpbnom * std::sqrt(2.0 / rho));
    mQat.setFlowCoefficient(Cq * f_at * pi * d * xatnom * std::sqrt(2.0 / rho));

    double qp, qt, qa, qb, pp, pt, pa, pb;
    auto solve = [&]() {
        const double qpa = mQpa.getFlow(cp, ca, Zcp, Zca);
        const double qbt = mQbt.getFlow(cb, ct, Zcb, Zct);
        const double qpb = mQpb.getFlow(cp, cb, Zcp, Zcb);
        const double qat = mQat.getFlow(ca, ct, Zca, Zct);
        qp = -qpa - qpb;
        qa = qpa - qat;
        qb = -qbt + qpb;
        qt = qat + qbt;
        pp = cp + qp * Zcp;
        pt = ct + qt * Zct;
        pa = ca + qa * Zca;
        pb = cb + qb * Zcb;
    };
    solve();

    bool cav = false;
    if (pa < 0.0) { ca = 0.0; Zca = 0.0; cav = true; }
    if (pb < 0.0) { cb = 0.0; Zcb = 0.0; cav = true; }
    if (pp < 0.0) { cp = 0.0; Zcp = 0.0; cav = true; }
    if (pt < 0.0) { ct = 0.0; Zct = 0.0; cav = true; }
    if (cav) { solve(); }

    *mpPP_p = pp;
    *mpPP_q = qp;
    *mpPT_p = pt;
    *mpPT_q = qt;
    *mpPA_p = pa;
    *mpPA_q = qa;
    *mpPB_p = pb;
    *mpPB_q = qb;
    *mpPC_p = cc;
    *mpPC_q = 0.0;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlled42Valve3, "Hydraulic")

} // namespace tlmhub
