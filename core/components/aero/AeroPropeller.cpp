#include "core/components/aero/AeroPropeller.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void AeroPropeller::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    addInputVariable("Up", "Air speed", "m/s", 1.25, &mpUp);
    addInputVariable("rho", "Air density", "kg/m3", 1.25, &mpRho);
    addInputVariable("dp", "Propeller diameter", "m", 1.0, &mpDp);
    addInputVariable("b1", "Thrust coefficient", "", 0.2, &mpB1);
    addInputVariable("b2", "Thrust coefficient", "", 0.2, &mpB2);
    addInputVariable("g1", "Torque coefficient", "", 0.205, &mpG1);
    addInputVariable("g2", "Torque coefficient", "", 0.2, &mpG2);
    addInputVariable("ct0", "Static thrust coefficient", "", 0.12, &mpCt0);
    addInputVariable("cp0", "Static power coefficient", "", 0.08, &mpCp0);
    addInputVariable("k", "Transition exponent", "", 4.0, &mpK);
    addOutputVariable("thrust", "Thrust", "N", 500.0, &mpThrust);
    addOutputVariable("torque", "Torque", "Nm", 0.0, &mpTorque);
    addOutputVariable("Pin", "Shaft power", "W", 0.0, &mpPin);
    addOutputVariable("Pout", "Propulsive power", "W", 0.0, &mpPout);
    addOutputVariable("Jp", "Advance ratio", "", 0.0, &mpJp);
}

void AeroPropeller::initialize()
{
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mThrust = *mpThrust;
    mC = *mpPmr1_c;
    // Nothing is written at initialisation.
}

void AeroPropeller::simulateOneTimestep()
{
    const double w = *mpPmr1_w;
    const double Up = *mpUp, rho = *mpRho, dp = *mpDp, b1 = *mpB1, b2 = *mpB2, g1 = *mpG1, g2 = *mpG2,
                 ct0 = *mpCt0, cp0 = *mpCp0, k = *mpK;
    const double dt = mTimestep;

    const double n = 0.00001 + 0.15915494309189535 * w;
    const double Xt = std::fabs(b1 - b2 * Up / (dp * n));
    const double Xq = std::fabs(g1 - g2 * Up / (dp * n));
    const double St = std::pow(1.0 / (std::pow(1.0 / ct0, k) + std::pow(Xt, -k)), 1.0 / k);
    const double Sq = std::pow(1.0 / (std::pow(1.0 / cp0, k) + std::pow(Xq, -k)), 1.0 / k);

    // Same outputs for both damped iterations: the generated Jacobian is the identity,
    // so the first iteration is exact and the second adds 0.67 * 0.
    double thrust = mThrust, c = mC;
    double torque = 0.0, Zc = 0.0, Pin = 0.0, Pout = 0.0, Jp = 0.0;
    for (int iter = 1; iter <= 2; ++iter) {
        const double F0 = thrust
                          + std::pow(dp, 3.0) * rho
                                * (0.025330295910584444 * b2 * Up
                                   + b1 * dp * (-2.5330295910584445e-7 - 0.004031441804149936 * w))
                                * (w * w) * St / (n * Xt);
        const double F1 = c
                          + std::pow(dp, 4.0) * rho
                                * (0.004031441804149936 * g2 * Up
                                   + dp * g1 * (-4.031441804149937e-8 - 0.000641623890917771 * w))
                                * (w * w) * Sq / (n * Xq);
        const double wgt = (iter == 1) ? 1.0 : 0.67;
        thrust = thrust - wgt * F0;
        c = c - wgt * F1;

        torque = c;
        // Uses the truncated 1/(2 pi) constant, as in the source.
        const double m = dp * (0.00001 + 0.159155 * w);
        const double Xq2 = std::fabs(g1 - g2 * Up / m);
        const double Sq2 = std::pow(1.0 / (std::pow(1.0 / cp0, k) + std::pow(Xq2, -k)), 1.0 / k);
        Zc = 0.0080629 * std::pow(dp, 5.0) * dt * rho * (g1 - g2 * Up / m) * w * Sq2 / Xq2;
        Pin = c * w;
        Pout = thrust * Up;
        Jp = Up / m;
    }
    mThrust = thrust;
    mC = c;

    *mpPmr1_c = c;
    *mpPmr1_Zc = Zc;
    *mpThrust = thrust;
    *mpTorque = torque;
    *mpPin = Pin;
    *mpPout = Pout;
    *mpJp = Jp;
}

TLMHUB_REGISTER_COMPONENT(AeroPropeller, "Aero")

} // namespace tlmhub
