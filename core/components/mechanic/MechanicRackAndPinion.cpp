#include "core/components/mechanic/MechanicRackAndPinion.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicRackAndPinion::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);
    addInputVariable("omega", "Gear ratio", "m/rad", 1.0, &mpOmega);
    addInputVariable("J", "Moment of inertia", "kg m^2", 1.0, &mpJ);
    addInputVariable("B", "Viscous friction coefficient", "Nm s/rad", 10.0, &mpB);
    addConstant("k", "Spring coefficient", "Nm/rad", 0.0, mK);
}

void MechanicRackAndPinion::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP1_me = getSafeNodeDataPtr(mpP1, NodeMechanic::EquivalentMass);
    mpP2_T = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Torque);
    mpP2_a = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Angle);
    mpP2_w = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::AngularVelocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::CharImpedance);

    // G(s) = s/(J s^2 + B s + k); only den[1] is updated in the step.
    mDen[0] = mK;
    mDen[1] = *mpB;
    mDen[2] = *mpJ;
    mFilter.initialize(mTimestep, mNum, mDen, 0.0, 0.0);
    mIntegrator.initialize(mTimestep, 0.0, 0.0);

    *mpP1_me = (*mpJ) * (*mpOmega);
}

void MechanicRackAndPinion::simulateOneTimestep()
{
    const double g = *mpOmega;
    const double J = *mpJ, B = *mpB;
    const double c1 = (*mpP1_c) * g;
    const double Zx1 = (*mpP1_Zx) * (g * g);
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;

    mDen[1] = B + Zx1 + Zx2;
    mFilter.setDen(mDen);
    const double w2 = mFilter.update(c1 - c2);
    const double v1 = -w2 * g;
    const double a2 = mIntegrator.update(w2);
    const double x1 = -a2 * g;
    const double f1 = (c1 + Zx1 * v1) / g;
    const double t2 = c2 + Zx2 * w2;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP1_me = J * g;
    *mpP2_T = t2;
    *mpP2_a = a2;
    *mpP2_w = w2;
}

TLMHUB_REGISTER_COMPONENT(MechanicRackAndPinion, "Mechanic")

} // namespace tlmhub
