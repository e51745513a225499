#include "core/components/hydraulic/Hydraulic43LoadSensingValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/FourWayValveFlow.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void Hydraulic43LoadSensingValve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPB = addPowerPort("PB", NodeType::Hydraulic);
    mpPL = addPowerPort("PL", NodeType::Hydraulic);

    addInputVariable("in", "Desired spool position", "m", 0.0, &mpIn);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_pb", "Fraction of spool circumference that is opening P-B", "-", 1.0, &mpFpb);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpFbt);
    addInputVariable("x_pa", "Spool overlap From Port P To A", "m", -1e-6, &mpXpa);
    addInputVariable("x_pb", "Spool overlap From Port P To B", "m", -1e-6, &mpXpb);
    addInputVariable("x_at", "Spool overlap From Port A To T", "m", -1e-6, &mpXat);
    addInputVariable("x_bt", "Spool overlap From Port B To T", "m", -1e-6, &mpXbt);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);

    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
}

void Hydraulic43LoadSensingValve::initialize()
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
    mpPL_p = getSafeNodeDataPtr(mpPL, NodeHydraulic::Pressure);
    mpPL_q = getSafeNodeDataPtr(mpPL, NodeHydraulic::Flow);
    mpPL_c = getSafeNodeDataPtr(mpPL, NodeHydraulic::WaveVariable);
    mpPL_Zc = getSafeNodeDataPtr(mpPL, NodeHydraulic::CharImpedance);

    const double xvmax = *mpXvmax;
    // The spool starts where the xv start value puts it (within the stroke).
    const double y0 = limit(*mpXv, -xvmax, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, -xvmax, xvmax);
}

void Hydraulic43LoadSensingValve::simulateOneTimestep()
{
    TlmWave P{*mpPP_c, *mpPP_Zc}, T{*mpPT_c, *mpPT_Zc}, A{*mpPA_c, *mpPA_Zc}, B{*mpPB_c, *mpPB_Zc};
    const double cload = *mpPL_c, Zcload = *mpPL_Zc;

    double xvin = *mpIn;
    const double Cq = *mpCq, rho = *mpRho, d = *mpD;
    const double f_pa = *mpFpa, f_pb = *mpFpb, f_at = *mpFat, f_bt = *mpFbt;
    const double x_pa = *mpXpa, x_pb = *mpXpb, x_at = *mpXat, x_bt = *mpXbt;
    const double xvmax = *mpXvmax;

    limitValue(xvin, -xvmax, xvmax);
    mSpool.update(xvin);
    const double xv = mSpool.value();

    const double xpanom = std::max(xv - x_pa, 0.0);
    const double xpbnom = std::max(-xv - x_pb, 0.0);
    const double xatnom = std::max(-xv - x_at, 0.0);
    const double xbtnom = std::max(xv - x_bt, 0.0);

    mQpa.setFlowCoefficient(Cq * f_pa * pi * d * xpanom * std::sqrt(2.0 / rho));
    mQpb.setFlowCoefficient(Cq * f_pb * pi * d * xpbnom * std::sqrt(2.0 / rho));
    mQat.setFlowCoefficient(Cq * f_at * pi * d * xatnom * std::sqrt(2.0 / rho));
    mQbt.setFlowCoefficient(Cq * f_bt * pi * d * xbtnom * std::sqrt(2.0 / rho));

    const FourWayValveFlows q = solveFourWayValve({mQpa, mQpb, mQat, mQbt}, P, T, A, B);

    // Load pressure: the port that is currently connected to supply.
    const double pload = (xv >= 0.0) ? A.pressure(q.a) : B.pressure(q.b);

    *mpPP_p = P.pressure(q.p);
    *mpPP_q = q.p;
    *mpPT_p = T.pressure(q.t);
    *mpPT_q = q.t;
    *mpPA_p = A.pressure(q.a);
    *mpPA_q = q.a;
    *mpPB_p = B.pressure(q.b);
    *mpPB_q = q.b;
    *mpPL_p = pload;
    if (Zcload != 0.0) { *mpPL_q = (pload - cload) / Zcload; }
    else { *mpPL_q = 0.0; }
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic43LoadSensingValve, "Hydraulic")

} // namespace tlmhub
