#include "core/components/mechanic/MechanicVelocityTransformer.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicVelocityTransformer::configure()
{
    addInputVariable("v", "Generated velocity", "m/s", 0.0, &mpV);
    mpXPort = addInputVariable("x", "Generated position", "m", 0.0, &mpX);
    addConstant("m_e", "Equivalent mass", "kg", 10.0, mMe);
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
}

void MechanicVelocityTransformer::initialize()
{
    mpPm1_f = getSafeNodeDataPtr(mpPm1, NodeMechanic::Force);
    mpPm1_x = getSafeNodeDataPtr(mpPm1, NodeMechanic::Position);
    mpPm1_v = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpPm1_c = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpPm1_Zx = getSafeNodeDataPtr(mpPm1, NodeMechanic::CharImpedance);
    mpPm1_me = getSafeNodeDataPtr(mpPm1, NodeMechanic::EquivalentMass);

    mXConnected = mpXPort->isConnected();
    if (mXConnected) {
        addWarningMessage("x is connected: the position input is used directly, make sure it is "
                          "consistent with v.");
    }

    const double v = *mpV;
    const double x = *mpX;
    mIntegrator.initialize(mTimestep, v, x);

    *mpPm1_me = mMe;
    *mpPm1_f = (*mpPm1_c) + (*mpPm1_Zx) * v;
    *mpPm1_x = x;
    *mpPm1_v = v;
}

void MechanicVelocityTransformer::simulateOneTimestep()
{
    const double v = *mpV;
    const double c = *mpPm1_c;
    const double Zx = *mpPm1_Zx;

    double x;
    if (mXConnected) {
        x = *mpX;
    } else {
        x = mIntegrator.update(v);
    }

    *mpPm1_f = c + Zx * v;
    *mpPm1_x = x;
    *mpPm1_v = v;
}

TLMHUB_REGISTER_COMPONENT(MechanicVelocityTransformer, "Mechanic")

} // namespace tlmhub
