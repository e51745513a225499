#include "core/components/hydraulic/HydraulicFixedDisplacementMotorQ.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicFixedDisplacementMotorQ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::MechanicRotational);

    addInputVariable("D_m", "Displacement", "m^3/rev", 5.0e-5, &mpDm);
    addInputVariable("B_m", "Viscous friction coefficient", "Nm/(rad/s)", 0.0, &mpBm);
    addInputVariable("C_lm", "Leakage coefficient", "m^3/(s Pa)", 1.0e-12, &mpClm);
    addInputVariable("J_m", "Moment of inertia", "kg m^2", 0.1, &mpJm);
}

void HydraulicFixedDisplacementMotorQ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_t = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::Torque);
    mpP3_a = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::Angle);
    mpP3_w = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::AngularVelocity);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::WaveVariable);
    mpP3_Zc = getSafeNodeDataPtr(mpP3, NodeMechanicRotational::CharImpedance);

    // Shaft starts at angle 0 and speed 0 regardless of the P3 start values.
    mIntegrator.initialize(mTimestep, 0.0, 0.0, 0.0, 0.0);
}

void HydraulicFixedDisplacementMotorQ::simulateOneTimestep()
{
    const double dm = *mpDm, B = *mpBm, cl = *mpClm, J = *mpJm;
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double c3 = *mpP3_c, Zc3 = *mpP3_Zc;

    const double dpe = dm / (pi * 2.0); // displacement per radian
    const double ble = B + Zc1 * dpe * dpe + Zc2 * dpe * dpe + Zc3;
    const double gamma = 1.0 / (cl * (Zc1 + Zc2) + 1.0);
    // Wave variables corrected for the leakage path.
    const double c1a = (cl * Zc2 + 1.0) * gamma * c1 + cl * gamma * Zc1 * c2;
    const double c2a = (cl * Zc1 + 1.0) * gamma * c2 + cl * gamma * Zc2 * c1;
    const double ct = c1a * dpe - c2a * dpe - c3;

    mIntegrator.setDamping(ble / J * mTimestep);
    mIntegrator.integrateWithUndo(ct / J);
    const double w3 = mIntegrator.valueFirst();
    const double a3 = mIntegrator.valueSecond();

    // Flow limited so that neither port pressure goes below zero.
    double q1a = -dpe * w3;
    q1a = std::fmin(std::fmax(q1a, -c1a / gamma / Zc1), c2a / gamma / Zc2);
    const double q2a = -q1a;

    const double p1 = c1a + gamma * Zc1 * q1a;
    const double p2 = c2a + gamma * Zc2 * q2a;

    const double q1leak = -cl * (p1 - p2);
    const double q2leak = -q1leak;
    const double q1 = q1a + q1leak;
    const double q2 = q2a + q2leak;

    const double t3 = c3 + w3 * Zc3;

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP3_t = t3;
    *mpP3_a = a3;
    *mpP3_w = w3;
}

TLMHUB_REGISTER_COMPONENT(HydraulicFixedDisplacementMotorQ, "Hydraulic")

} // namespace tlmhub
