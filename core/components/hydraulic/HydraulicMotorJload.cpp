#include "core/components/hydraulic/HydraulicMotorJload.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void HydraulicMotorJload::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpPm1 = addPowerPort("Pm1", NodeType::MechanicRotational);

    addInputVariable("Dm", "Displacement", "m^3", 5e-5, &mpDm);
    addInputVariable("Cim", "Leak coeff.", "m^3/(s Pa)", 0.0, &mpCim);
    addInputVariable("Bm", "Visc. friction coeff.", "Nms/rad", 0.0, &mpBm);
    addInputVariable("Jm", "Moment of inertia", "kg m^2", 0.1, &mpJm);
}

void HydraulicMotorJload::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpPm1_t = getSafeNodeDataPtr(mpPm1, NodeMechanicRotational::Torque);
    mpPm1_a = getSafeNodeDataPtr(mpPm1, NodeMechanicRotational::Angle);
    mpPm1_w = getSafeNodeDataPtr(mpPm1, NodeMechanicRotational::AngularVelocity);
    mpPm1_c = getSafeNodeDataPtr(mpPm1, NodeMechanicRotational::WaveVariable);
    mpPm1_Zc = getSafeNodeDataPtr(mpPm1, NodeMechanicRotational::CharImpedance);

    // The shaft starts from the start values of its node.
    mAngle = *mpPm1_a;
    mW = *mpPm1_w;
    mDrive = *mpDm / (2.0 * pi) * (*mpP1_p - *mpP2_p) - *mpPm1_t;
}

void HydraulicMotorJload::simulateOneTimestep()
{
    const double h = mTimestep;
    const double k = *mpDm / (2.0 * pi); // displacement per radian
    const double Cim = *mpCim, Bm = *mpBm, Jm = *mpJm;
    const double cm = *mpPm1_c, Zcm = *mpPm1_Zc;
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;

    // Jm*dw/dt + Bm*w = k*(p1 - p2) - T, trapezoidal:
    //   w = a*drive + b with the previous step in b.
    const double a = h / (2.0 * Jm + Bm * h);
    const double b = (h * mDrive + (2.0 * Jm - Bm * h) * mW) / (2.0 * Jm + Bm * h);

    // Together with q2 = k*w + Cim*(p1 - p2), p1 = c1 - Zc1*q2, p2 = c2 + Zc2*q2 and
    // T = cm + Zcm*w everything is linear in w. A port that would go below zero is
    // pinned at 0 (c = Zc = 0) and the system solved again.
    double w = 0, q2 = 0, p1 = 0, p2 = 0;
    auto solve = [&]() {
        const double Z = Zc1 + Zc2;
        // q2 = (k*w + Cim*(c1 - c2))/(1 + Cim*Z); dp = (c1 - c2) - Z*q2.
        const double g = 1.0 + Cim * Z;
        const double dp0 = (c1 - c2) - Z * Cim * (c1 - c2) / g; // dp at w = 0
        const double dpw = -Z * k / g;                           // d(dp)/dw
        // w = a*(k*dp - cm - Zcm*w) + b
        w = (a * (k * dp0 - cm) + b) / (1.0 - a * (k * dpw - Zcm));
        q2 = (k * w + Cim * (c1 - c2)) / g;
        p1 = c1 - Zc1 * q2;
        p2 = c2 + Zc2 * q2;
    };
    solve();
    bool cav = false;
    if (p1 < 0.0) { c1 = 0.0; Zc1 = 0.0; cav = true; }
    if (p2 < 0.0) { c2 = 0.0; Zc2 = 0.0; cav = true; }
    if (cav) { solve(); }

    const double T = cm + Zcm * w;
    mAngle += h / 2.0 * (w + mW);
    mW = w;
    mDrive = k * (p1 - p2) - T;

    *mpP1_p = p1;
    *mpP1_q = -q2;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpPm1_t = T;
    *mpPm1_a = mAngle;
    *mpPm1_w = w;
}

TLMHUB_REGISTER_COMPONENT(HydraulicMotorJload, "Hydraulic")

} // namespace tlmhub
