#include "core/components/mechanic/MechanicAngularVelocityTransformer.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicAngularVelocityTransformer::configure()
{
    addInputVariable("omega", "Generated angular velocity", "rad/s", 0.0, &mpOmega);
    mpOut = addPowerPort("out", NodeType::MechanicRotational);
}

void MechanicAngularVelocityTransformer::initialize()
{
    mpOut_T = getSafeNodeDataPtr(mpOut, NodeMechanicRotational::Torque);
    mpOut_a = getSafeNodeDataPtr(mpOut, NodeMechanicRotational::Angle);
    mpOut_w = getSafeNodeDataPtr(mpOut, NodeMechanicRotational::AngularVelocity);
    mpOut_c = getSafeNodeDataPtr(mpOut, NodeMechanicRotational::WaveVariable);
    mpOut_Zc = getSafeNodeDataPtr(mpOut, NodeMechanicRotational::CharImpedance);

    // Angle starts at the port's start angle; nothing is written here.
    mIntegrator.initialize(mTimestep, *mpOmega, *mpOut_a);
}

void MechanicAngularVelocityTransformer::simulateOneTimestep()
{
    const double w = *mpOmega;
    const double c = *mpOut_c;
    const double Zc = *mpOut_Zc;

    const double a = mIntegrator.update(w);
    const double T = c + Zc * w;

    *mpOut_T = T;
    *mpOut_a = a;
    *mpOut_w = w;
}

TLMHUB_REGISTER_COMPONENT(MechanicAngularVelocityTransformer, "Mechanic")

} // namespace tlmhub
