#include "core/components/hydraulic/Hydraulic42DirectionalValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/FourWayValveFlow.h"

#include <cmath>

namespace tlmhub {

void Hydraulic42DirectionalValve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPB = addPowerPort("PB", NodeType::Hydraulic);

    addOutputVariable("xv", "Spool position", "m", &mpXv);
    addInputVariable("in", "Open (> 0.5) or closed", "m", 0.0, &mpIn);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpFbt);
    addInputVariable("f_pb", "Fraction of spool circumference that is opening P-B", "-", 1.0, &mpFpb);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);
    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
}

void Hydraulic42DirectionalValve::initialize()
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

    // Starts from the clamped *input* (not the xv start value), per reference.
    const double xvmax = *mpXvmax;
    const double y0 = limit(*mpIn, 0.0, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, 0.0, xvmax);
}

void Hydraulic42DirectionalValve::simulateOneTimestep()
{
    TlmWave P{*mpPP_c, *mpPP_Zc}, T{*mpPT_c, *mpPT_Zc}, A{*mpPA_c, *mpPA_Zc}, B{*mpPB_c, *mpPB_Zc};
    const double Cq = *mpCq, rho = *mpRho, xvmax = *mpXvmax, d = *mpD;
    const double f_pa = *mpFpa, f_pb = *mpFpb, f_at = *mpFat, f_bt = *mpFbt;

    if (doubleToBool(*mpIn)) { mSpool.update(xvmax); }
    else { mSpool.update(0.0); }
    const double xv = mSpool.value();

    const double xpanom = xv;
    const double xpbnom = xvmax - xv;
    const double xatnom = xvmax - xv;
    const double xbtnom = xv;

    mQpa.setFlowCoefficient(Cq * f_pa * pi * d * xpanom * std::sqrt(2.0 / rho));
    mQpb.setFlowCoefficient(Cq * f_pb * pi * d * xpbnom * std::sqrt(2.0 / rho));
    mQat.setFlowCoefficient(Cq * f_at * pi * d * xatnom * std::sqrt(2.0 / rho));
    mQbt.setFlowCoefficient(Cq * f_bt * pi * d * xbtnom * std::sqrt(2.0 / rho));

    const FourWayValveFlows q = solveFourWayValve({mQpa, mQpb, mQat, mQbt}, P, T, A, B);

    *mpPP_p = P.pressure(q.p);
    *mpPP_q = q.p;
    *mpPT_p = T.pressure(q.t);
    *mpPT_q = q.t;
    *mpPA_p = A.pressure(q.a);
    *mpPA_q = q.a;
    *mpPB_p = B.pressure(q.b);
    *mpPB_q = q.b;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(Hydraulic42DirectionalValve, "Hydraulic")

} // namespace tlmhub
