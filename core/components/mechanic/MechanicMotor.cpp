#include "core/components/mechanic/MechanicMotor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicMotor::configure()
{
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    addInputVariable("omega_ref", "Reference angular velocity", "rad/s", 0.0, &mpOmegaRef);
    addInputVariable("K_p", "Proportional gain", "", 10.0, &mpKp);
    addInputVariable("K_i", "Integrating gain", "", 100.0, &mpKi);
    addInputVariable("K_d", "Derivative gain", "", 100.0, &mpKd);
}

void MechanicMotor::initialize()
{
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);

    mIntegrator.initialize(mTimestep, 0.0, 0.0);
    // G(s) = s
    const double num[2] = {0.0, 1.0};
    const double den[2] = {1.0, 0.0};
    mDerivator.initialize(mTimestep, num, den, 0.0, 0.0);
}

void MechanicMotor::simulateOneTimestep()
{
    // Port speed is counted positive into the component, the controller outward.
    const double w1 = -(*mpP1_w);
    const double e = (*mpOmegaRef) - w1;

    const double xp = (*mpKp) * e;
    const double xi = (*mpKi) * mIntegrator.update(e);
    const double xd = (*mpKd) * mDerivator.update(e);
    const double t = xp + xi + xd;

    *mpP1_c = t;
    *mpP1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(MechanicMotor, "Mechanic")

} // namespace tlmhub
