#include "core/components/signal/SignalAttitudeControl.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void SignalAttitudeControl::configure()
{
    addInputVariable("phiref", "Roll reference", "rad", 0.0, &mpPhiref);
    addInputVariable("thetaref", "Pitch reference", "rad", 0.0, &mpThetaref);
    addInputVariable("psiref", "Heading reference", "rad", 0.0, &mpPsiref);
    addInputVariable("phimax", "Maximum bank angle for turning", "rad", 1.0, &mpPhimax);
    addInputVariable("phi", "Roll angle", "rad", 0.0, &mpPhi);
    addInputVariable("theta", "Pitch angle", "rad", 0.0, &mpTheta);
    addInputVariable("psi", "Heading angle", "rad", 0.0, &mpPsi);
    addInputVariable("beta", "Side-slip angle", "rad", 0.0, &mpBeta);
    addInputVariable("Qb", "Pitch rate", "rad/s", 0.0, &mpQb);
    addInputVariable("Rb", "Yaw rate", "rad/s", 0.0, &mpRb);
    addInputVariable("Ub", "Speed", "m/s", 0.0, &mpUb);
    addInputVariable("Kphi", "Roll gain", "rad", 3.0, &mpKphi);
    addInputVariable("Kphipsi", "Heading-to-roll gain", "rad", 2.0, &mpKphipsi);
    addInputVariable("Kelev", "Elevator gain", "rad", 4.0, &mpKelev);
    addInputVariable("Kdelev", "Elevator rate gain", "rad", 1.0, &mpKdelev);
    addInputVariable("Krud", "Rudder gain", "rad", 1.0, &mpKrud);
    addInputVariable("Kdrud", "Rudder rate gain", "", 1.0, &mpKdrud);
    addInputVariable("u1min", "Aileron lower limit", "rad", -0.9, &mpU1min);
    addInputVariable("u1max", "Aileron upper limit", "rad", 0.9, &mpU1max);
    addInputVariable("u2min", "Elevator lower limit", "rad", -0.7, &mpU2min);
    addInputVariable("u2max", "Elevator upper limit", "rad", 0.7, &mpU2max);
    addInputVariable("u3min", "Rudder lower limit", "rad", -0.7, &mpU3min);
    addInputVariable("u3max", "Rudder upper limit", "rad", 0.7, &mpU3max);
    addInputVariable("U0", "Reference speed", "m/s", 100.0, &mpU0);
    addOutputVariable("uaerL", "Left aileron command", "rad", 0.0, &mpUaerL);
    addOutputVariable("uaerR", "Right aileron command", "rad", 0.0, &mpUaerR);
    addOutputVariable("uelev", "Elevator command", "rad", 0.0, &mpUelev);
    addOutputVariable("urud", "Rudder command", "rad", 0.0, &mpUrud);
}

void SignalAttitudeControl::initialize()
{
    simulateOneTimestep();
}

void SignalAttitudeControl::simulateOneTimestep()
{
    const double U0 = *mpU0, Ub = *mpUb;
    const double Kv = Power(U0, 2) / (Power(U0, 2) + Power(Abs(Ub), 2));
    const double u1cmin = Kv * (*mpU1min);
    const double u1cmax = Kv * (*mpU1max);
    const double u2cmin = Kv * (*mpU2min);
    const double u2cmax = Kv * (*mpU2max);
    const double u3cmin = *mpU3min;
    const double u3cmax = *mpU3max;
    const double phimax = *mpPhimax;
    const double turn = limit(*mpKphipsi * diffAngle(*mpPsiref, *mpPsi), -phimax, phimax);
    const double roll = diffAngle(*mpPhiref, *mpPhi) + turn;
    // Right aileron: same product negated, bounds given reversed (limit swaps them).
    *mpUaerL = limit(*mpKphi * Kv * roll, u1cmin, u1cmax);
    *mpUaerR = limit(-(*mpKphi * Kv * roll), u1cmax, u1cmin);
    *mpUelev = limit(-(Kv * (-(*mpKdelev * *mpQb) + *mpKelev * diffAngle(*mpThetaref, *mpTheta))), u2cmin, u2cmax);
    *mpUrud = limit(-(Kv * (*mpBeta * *mpKrud + *mpKdrud * *mpRb)), u3cmin, u3cmax);
}

TLMHUB_REGISTER_COMPONENT(SignalAttitudeControl, "Signal")

} // namespace tlmhub
