#include "core/components/hydraulic/HydraulicFourWaySpoolValveBase.h"

#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/FourWayValveFlow.h"

#include <cmath>

namespace tlmhub {

void HydraulicFourWaySpoolValveBase::configure()
{
    mpPP = addPowerPort("PP", NodeType::Hydraulic);
    mpPT = addPowerPort("PT", NodeType::Hydraulic);
    mpPA = addPowerPort("PA", NodeType::Hydraulic);
    mpPB = addPowerPort("PB", NodeType::Hydraulic);

    addOutputVariable("xv", "Spool position", "m", 0.0, &mpXv);
    addInputVariable("in", "Desired spool position", "m", 0.0, &mpIn);
    addInputVariable("C_q", "Flow Coefficient", "-", 0.67, &mpCq);
    addInputVariable("rho", "Oil Density", "kg/m^3", mDefaults.rho, &mpRho);
    addInputVariable("d", "Spool Diameter", "m", 0.01, &mpD);
    addInputVariable("x_vmax", "Maximum Spool Displacement", "m", 0.01, &mpXvmax);
    addEdgeInputs();

    addConstant("omega_h", "Resonance Frequency", "rad/s", 100.0, mOmegah);
    addConstant("delta_h", "Damping Factor", "-", mDefaults.deltah, mDeltah);
}

double HydraulicFourWaySpoolValveBase::edge(double f, double x) const
{
    return *mpCq * f * pi * *mpD * x * std::sqrt(2.0 / *mpRho);
}

void HydraulicFourWaySpoolValveBase::initialize()
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

    const double xvmax = *mpXvmax;
    const double xvmin = mDefaults.negativeSpool ? -xvmax : 0.0;
    const double y0 = limit(*mpXv, xvmin, xvmax);
    const double num[3] = {1.0, 0.0, 0.0};
    const double den[3] = {1.0, 2.0 * mDeltah / mOmegah, 1.0 / (mOmegah * mOmegah)};
    mSpool.initialize(mTimestep, num, den, y0, y0, xvmin, xvmax);
}

void HydraulicFourWaySpoolValveBase::simulateOneTimestep()
{
    TlmWave P{*mpPP_c, *mpPP_Zc}, T{*mpPT_c, *mpPT_Zc}, A{*mpPA_c, *mpPA_Zc}, B{*mpPB_c, *mpPB_Zc};
    const double xvmax = *mpXvmax;

    // The demand is limited to the stroke; the 4/2 types have no negative side.
    double xvin = *mpIn;
    limitValue(xvin, mDefaults.negativeDemand ? -xvmax : 0.0, xvmax);
    mSpool.update(xvin);
    const double xv = mSpool.value();

    const Edges K = edges(xv, xvmax);
    mQpa.setFlowCoefficient(K.pa);
    mQpb.setFlowCoefficient(K.pb);
    mQat.setFlowCoefficient(K.at);
    mQbt.setFlowCoefficient(K.bt);
    mQpt.setFlowCoefficient(K.pt);

    const FourWayValveFlows q = solveFourWayValve({mQpa, mQpb, mQat, mQbt, &mQpt}, P, T, A, B);

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

} // namespace tlmhub
