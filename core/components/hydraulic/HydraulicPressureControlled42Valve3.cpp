#include "core/components/hydraulic/HydraulicPressureControlled42Valve3.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/FourWayValveFlow.h"

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
    TlmWave P{*mpPP_c, *mpPP_Zc}, T{*mpPT_c, *mpPT_Zc}, A{*mpPA_c, *mpPA_Zc}, B{*mpPB_c, *mpPB_Zc};
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

    const FourWayValveFlows q = solveFourWayValve({mQpa, mQpb, mQat, mQbt}, P, T, A, B);

    *mpPP_p = P.pressure(q.p);
    *mpPP_q = q.p;
    *mpPT_p = T.pressure(q.t);
    *mpPT_q = q.t;
    *mpPA_p = A.pressure(q.a);
    *mpPA_q = q.a;
    *mpPB_p = B.pressure(q.b);
    *mpPB_q = q.b;
    *mpPC_p = cc;
    *mpPC_q = 0.0;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPressureControlled42Valve3, "Hydraulic")

} // namespace tlmhub
