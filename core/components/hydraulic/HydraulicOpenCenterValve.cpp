#include "core/components/hydraulic/HydraulicOpenCenterValve.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/FourWayValveFlow.h"

#include <algorithm>
#include <cmath>

namespace tlmhub {

void HydraulicOpenCenterValve::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPB = addPowerPort("PB", NodeType::Hydraulic);
    mpPC1 = addPowerPort("PC1", NodeType::Hydraulic);
    mpPC2 = addPowerPort("PC2", NodeType::Hydraulic);

    addInputVariable("in", "Desired spool position", "m", 0.0, &mpIn);
    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("C_q", "Flow coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("d", "Spool diameter", "m", 0.01, &mpD);
    addInputVariable("f_pa", "Fraction of spool circumference that is opening P-A", "-", 1.0, &mpFpa);
    addInputVariable("f_pb", "Fraction of spool circumference that is opening P-B", "-", 1.0, &mpFpb);
    addInputVariable("f_at", "Fraction of spool circumference that is opening A-T", "-", 1.0, &mpFat);
    addInputVariable("f_bt", "Fraction of spool circumference that is opening B-T", "-", 1.0, &mpFbt);
    addInputVariable("f_cc", "Fraction of spool circumference that is opening C1-C2", "-", 1.0, &mpFcc);
    addInputVariable("x_pa", "Spool overlap From Port P To A", "m", -1e-6, &mpXpa);
    addInputVariable("x_pb", "Spool overlap From Port P To B", "m", -1e-6, &mpXpb);
    addInputVariable("x_at", "Spool overlap From Port A To T", "m", -1e-6, &mpXat);
    addInputVariable("x_bt", "Spool overlap From Port B To T", "m", -1e-6, &mpXbt);
    addInputVariable("x_cc", "Spool overlap of the open centre C1-C2", "m", -1e-6, &mpXcc);
    addInputVariable("x_vmax", "Maximum spool displacement", "m", 0.01, &mpXvmax);

    addConstant("omega_h", "Resonance frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping factor", "-", 1.0, mDeltah);
}

void HydraulicOpenCenterValve::initialize()
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
    mpPC1_p = getSafeNodeDataPtr(mpPC1, NodeHydraulic::Pressure);
    mpPC1_q = getSafeNodeDataPtr(mpPC1, NodeHydraulic::Flow);
    mpPC1_c = getSafeNodeDataPtr(mpPC1, NodeHydraulic::WaveVariable);
    mpPC1_Zc = getSafeNodeDataPtr(mpPC1, NodeHydraulic::CharImpedance);
    mpPC2_p = getSafeNodeDataPtr(mpPC2, NodeHydraulic::Pressure);
    mpPC2_q = getSafeNodeDataPtr(mpPC2, NodeHydraulic::Flow);
    mpPC2_c = getSafeNodeDataPtr(mpPC2, NodeHydraulic::WaveVariable);
    mpPC2_Zc = getSafeNodeDataPtr(mpPC2, NodeHydraulic::CharImpedance);

    const double xvmax = *mpXvmax;
    // The spool starts where the xv start value puts it (within the stroke).
    const double y0 = limit(*mpXv, -xvmax, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, -xvmax, xvmax);
}

void HydraulicOpenCenterValve::simulateOneTimestep()
{
    TlmWave P{*mpPP_c, *mpPP_Zc}, T{*mpPT_c, *mpPT_Zc}, A{*mpPA_c, *mpPA_Zc}, B{*mpPB_c, *mpPB_Zc};
    TlmWave C1{*mpPC1_c, *mpPC1_Zc}, C2{*mpPC2_c, *mpPC2_Zc};

    double xvin = *mpIn;
    const double Cq = *mpCq, rho = *mpRho, d = *mpD;
    const double f_pa = *mpFpa, f_pb = *mpFpb, f_at = *mpFat, f_bt = *mpFbt, f_cc = *mpFcc;
    const double x_pa = *mpXpa, x_pb = *mpXpb, x_at = *mpXat, x_bt = *mpXbt, x_cc = *mpXcc;
    const double xvmax = *mpXvmax;

    limitValue(xvin, -xvmax, xvmax);
    mSpool.update(xvin);
    const double xv = mSpool.value();

    const double xpanom = std::max(xv - x_pa, 0.0);
    const double xpbnom = std::max(-xv - x_pb, 0.0);
    const double xatnom = std::max(-xv - x_at, 0.0);
    const double xbtnom = std::max(xv - x_bt, 0.0);
    const double xccnom = xvmax - std::max(std::min(xvmax, std::fabs(xv) - x_cc), 0.0);

    mQpa.setFlowCoefficient(Cq * f_pa * pi * d * xpanom * std::sqrt(2.0 / rho));
    mQpb.setFlowCoefficient(Cq * f_pb * pi * d * xpbnom * std::sqrt(2.0 / rho));
    mQat.setFlowCoefficient(Cq * f_at * pi * d * xatnom * std::sqrt(2.0 / rho));
    mQbt.setFlowCoefficient(Cq * f_bt * pi * d * xbtnom * std::sqrt(2.0 / rho));
    mQcc.setFlowCoefficient(Cq * f_cc * pi * d * xccnom * std::sqrt(2.0 / rho));

    const FourWayValveFlows q = solveFourWayValve({mQpa, mQpb, mQat, mQbt}, P, T, A, B);

    // The open centre C1-C2 shares no port with the metering edges, so it is solved on its
    // own, with the same cavitation rule.
    double qcc = mQcc.getFlow(C1.c, C2.c, C1.Zc, C2.Zc);
    bool centreCavitates = cavitates(C1, -qcc);
    centreCavitates = cavitates(C2, qcc) || centreCavitates;
    if (centreCavitates) { qcc = mQcc.getFlow(C1.c, C2.c, C1.Zc, C2.Zc); }

    *mpPP_p = P.pressure(q.p);
    *mpPP_q = q.p;
    *mpPT_p = T.pressure(q.t);
    *mpPT_q = q.t;
    *mpPA_p = A.pressure(q.a);
    *mpPA_q = q.a;
    *mpPB_p = B.pressure(q.b);
    *mpPB_q = q.b;
    *mpPC1_p = C1.pressure(-qcc);
    *mpPC1_q = -qcc;
    *mpPC2_p = C2.pressure(qcc);
    *mpPC2_q = qcc;
    *mpXv = xv;
}

TLMHUB_REGISTER_COMPONENT(HydraulicOpenCenterValve, "Hydraulic")

} // namespace tlmhub
