#include "core/components/signal/SignalAttitudeTVCcontrol.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalAttitudeTVCcontrol::configure()
{
    addInputVariable("thetaref", "Pitch reference", "rad", 0.0, &mpThetaref);
    addInputVariable("psiref", "Heading reference", "rad", 0.0, &mpPsiref);
    addInputVariable("phi", "Roll angle (unused)", "rad", 0.0, &mpPhi);
    addInputVariable("theta", "Pitch angle", "rad", 0.0, &mpTheta);
    addInputVariable("psi", "Heading angle", "rad", 0.0, &mpPsi);
    addInputVariable("Qb", "Pitch rate", "rad/s", 0.0, &mpQb);
    addInputVariable("Rb", "Yaw rate", "rad/s", 0.0, &mpRb);
    addInputVariable("Kelev", "Elevator gain", "", 4.0, &mpKelev);
    addInputVariable("Krud", "Rudder gain", "", 1.0, &mpKrud);
    addInputVariable("KQrud", "Pitch rate gain", "", 1.0, &mpKQrud);
    addInputVariable("KRrud", "Yaw rate gain", "", 1.0, &mpKRrud);
    addInputVariable("umin", "Lower limit", "rad", -0.9, &mpUmin);
    addInputVariable("umax", "Upper limit", "rad", 0.9, &mpUmax);
    addOutputVariable("uelev", "Elevator (pitch) command", "rad", 0.0, &mpUelev);
    addOutputVariable("urud", "Rudder (yaw) command", "rad", 0.0, &mpUrud);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"phi"}, false);
}

void SignalAttitudeTVCcontrol::initialize()
{
    simulateOneTimestep();
}

void SignalAttitudeTVCcontrol::simulateOneTimestep()
{
    const double umin = *mpUmin, umax = *mpUmax;
    *mpUelev = limit(*mpKelev * (-(*mpKQrud * *mpQb) + diffAngle(*mpThetaref, *mpTheta)), umin, umax);
    *mpUrud = limit(*mpKrud * (-(*mpKRrud * *mpRb) + diffAngle(*mpPsiref, *mpPsi)), umin, umax);
}

TLMHUB_REGISTER_COMPONENT(SignalAttitudeTVCcontrol, "Signal")

} // namespace tlmhub
