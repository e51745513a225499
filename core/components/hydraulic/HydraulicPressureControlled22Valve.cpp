#include "core/components/hydraulic/HydraulicPressureControlled22Valve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicPressureControlled22Valve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPC = addPowerPort("PC", NodeType::Hydraulic);

    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
    addInputVariable("Fs_min", "Pilot pressure where the spool starts to move", "Pa", 1e5, &mpFsmin);
    addInputVariable("Fs_max", "Pilot pressure for full spool stroke", "Pa", 1e6, &mpFsmax);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpfpa);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpfbt);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);
    addOutputVariable("x_v", "Spool position", "m", 0.0, &mpXv);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"f_bt"}, false);
}

void HydraulicPressureControlled22Valve::initialize()
{
    mpPP_p = getSafeNodeDataPtr(mpPP, NodeHydraulic::Pressure);
    mpPP_q = getSafeNodeDataPtr(mpPP, NodeHydraulic::Flow);
    mpPP_c = getSafeNodeDataPtr(mpPP, NodeHydraulic::WaveVariable);
    mpPP_Zc = getSafeNodeDataPtr(mpPP, NodeHydraulic::CharImpedance);
    mpPA_p = getSafeNodeDataPtr(mpPA, NodeHydraulic::Pressure);
    mpPA_q = getSafeNodeDataPtr(mpPA, NodeHydraulic::Flow);
    mpPA_c = getSafeNodeDataPtr(mpPA, NodeHydraulic::WaveVariable);
    mpPA_Zc = getSafeNodeDataPtr(mpPA, NodeHydraulic::CharImpedance);
    mpPC_p = getSafeNodeDataPtr(mpPC, NodeHydraulic::Pressure);
    mpPC_q = getSafeNodeDataPtr(mpPC, NodeHydraulic::Flow);
    mpPC_c = getSafeNodeDataPtr(mpPC, NodeHydraulic::WaveVariable);
    mpPC_Zc = getSafeNodeDataPtr(mpPC, NodeHydraulic::CharImpedance);

    // The spool always starts at 0 (the x_v start value is not used).
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, 0.0, 0.0, 0.0, *mpXvmax);
}

void HydraulicPressureControlled22Valve::simulateOneTimestep()
{
    double cp = *mpPP_c, Zcp = *mpPP_Zc;
    double ca = *mpPA_c, Zca = *mpPA_Zc;
    const double cc = *mpPC_c; // pilot wave variable
    const double Fs_min = *mpFsmin, Fs_max = *mpFsmax, Cq = *mpCq, rho = *mpRho, d = *mpD;
    const double f_pa = *mpfpa; // f_bt is declared but unused by this type
    const double xvmax = *mpXvmax;

    mSpool.update(std::min(1.0, std::max(0.0, (cc - Fs_min) / (Fs_max - Fs_min))) * xvmax);
    const double xv = mSpool.value();

    mQpa.setFlowCoefficient(Cq * f_pa * pi * d * xv * std::sqrt(2.0 / rho));

    double qp, qa, pp, pa;
    auto solve = [&]() {
        const double qpa = mQpa.getFlow(cp, ca, Zcp, Zca);
        qp = -qpa;
        qa = qpa;
        pp = cp + qp * Zcp;
        pa = ca + qa * Zca;
    };
    solve();

    bool cav = false;
    if (pa < 0.0) { ca = 0.0; Zca = 0.0; cav = true; }
    if (pp < 0.0) { cp = 0.0; Zcp = 0.0; cav = true; }
    if (cav) { solve(); }

    *mpPP_p = pp;
    *mpPP_q = qp;
    *mpPA_p = pa;
    *mpPA_q = qa;
    *mpPC_p = cc;
    *mpPC_q = 0.0;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlled22Valve, "Hydraulic")

} // namespace tlmhub
