#include "core/components/hydraulic/HydraulicPiston.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void HydraulicPiston::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);

    addInputVariable("A1", "Piston area 1", "m^2", 0.001, &mpA1);
    addInputVariable("A2", "Piston area 2", "m^2", 0.001, &mpA2);
    addInputVariable("V01", "Dead Volume Piston 1", "m^3", 0.001, &mpV01);
    addInputVariable("V02", "Dead Volume Piston 2", "m^3", 0.001, &mpV02);
    addInputVariable("SL", "Stroke", "m", 0.5, &mpSL);
    addInputVariable("betae", "Bulk modulus", "Pa", 1.7e7, &mpBetae);
    addInputVariable("alpha", "Damp. factor", "-", 0.0, &mpAlpha);
}

void HydraulicPiston::initialize()
{
    double* p1 = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    double* p2 = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPm1_x = getSafeNodeDataPtr(mpPm1, NodeMechanic::Position);
    mpPm1_v = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpPm1_c = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpPm1_Zc = getSafeNodeDataPtr(mpPm1, NodeMechanic::CharImpedance);

    // All waves start at the start pressures; one step then fills the nodes.
    mC1 = mCp1 = *p1;
    mC2 = mCp2 = *p2;
    simulateOneTimestep();
}

void HydraulicPiston::simulateOneTimestep()
{
    const double A1 = *mpA1, A2 = *mpA2, SL = *mpSL, alpha = *mpAlpha;
    const double x = *mpPm1_x, v = *mpPm1_v;

    // Chamber 1 grows as the rod moves to negative x, chamber 2 shrinks.
    const double V1 = *mpV01 + A1 * limit(-x, 0.0, SL);
    const double V2 = *mpV02 + A2 * limit(SL + x, 0.0, SL);
    const double Zc1 = *mpBetae * mTimestep / ((1.0 - alpha) * V1);
    const double Zc2 = *mpBetae * mTimestep / ((1.0 - alpha) * V2);

    // Each chamber is a TLM volume between its oil port and the piston face, whose
    // flow is the displaced volume A*v; waves are low-pass filtered with alpha.
    const double qFace1 = A1 * v;
    const double qFace2 = -A2 * v;
    const double c1New = mCp1 + 2.0 * qFace1 * Zc1;
    const double c2New = mCp2 + 2.0 * qFace2 * Zc2;
    const double cp1New = mC1 + 2.0 * *mpP1_q * Zc1;
    const double cp2New = mC2 + 2.0 * *mpP2_q * Zc2;
    mC1 = (1.0 - alpha) * c1New + alpha * mC1;
    mCp1 = (1.0 - alpha) * cp1New + alpha * mCp1;
    mC2 = (1.0 - alpha) * c2New + alpha * mC2;
    mCp2 = (1.0 - alpha) * cp2New + alpha * mCp2;

    *mpP1_c = mC1;
    *mpP1_Zc = Zc1;
    *mpP2_c = mC2;
    *mpP2_Zc = Zc2;
    *mpPm1_c = A1 * mCp1 - A2 * mCp2;
    *mpPm1_Zc = A1 * A1 * Zc1 + A2 * A2 * Zc2;
}

TLMHUB_REGISTER_COMPONENT(HydraulicPiston, "Hydraulic")

} // namespace tlmhub
