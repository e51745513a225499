#include "core/components/mechanic/MechanicRotationalInertiaWithCoulombFriction.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicRotationalInertiaWithCoulombFriction::configure()
{
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);
    addInputVariable("J", "Moment of inertia", "kg m^2", 1.0, &mpJ);
    addInputVariable("B", "Viscous friction coefficient", "Nm s/rad", 10.0, &mpB);
    addInputVariable("a_min", "Minimum angle of P2", "rad", -1.0e300, &mpAMin);
    addInputVariable("a_max", "Maximum angle of P2", "rad", 1.0e300, &mpAMax);
    addConstant("t_s", "Static friction torque", "Nm", 50.0, mTs);
    addConstant("t_k", "Kinetic friction torque", "Nm", 45.0, mTk);
}

void MechanicRotationalInertiaWithCoulombFriction::initialize()
{
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Torque);
    mpP1_a = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Angle);
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);
    mpP2_T = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Torque);
    mpP2_a = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::Angle);
    mpP2_w = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::AngularVelocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanicRotational::CharImpedance);

    if (*mpP1_a != -(*mpP2_a)) {
        addWarningMessage("Start angles of P1 and P2 are not opposite.");
    }
    if (*mpP1_w != -(*mpP2_w)) {
        addWarningMessage("Start angular velocities of P1 and P2 are not opposite.");
    }

    const double J = *mpJ;
    // Friction levels are fixed here; the step never updates them.
    mIntegrator.initialize(mTimestep, 0.0, mTs / J, mTk / J, (*mpP1_T) - (*mpP2_T), *mpP2_a, *mpP2_w);
}

void MechanicRotationalInertiaWithCoulombFriction::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;
    const double J = *mpJ, B = *mpB;

    mIntegrator.setDamping((B + Zx1 + Zx2) / J * mTimestep);
    mIntegrator.integrateWithUndo((c1 - c2) / J);
    double w2 = mIntegrator.valueFirst();
    double a2 = mIntegrator.valueSecond();

    if (a2 < *mpAMin) {
        a2 = *mpAMin;
        w2 = 0.0;
        mIntegrator.initializeValues((c1 - c2) / J, a2, w2);
    }
    if (a2 > *mpAMax) {
        a2 = *mpAMax;
        w2 = 0.0;
        mIntegrator.initializeValues((c1 - c2) / J, a2, w2);
    }

    const double w1 = -w2;
    const double a1 = -a2;
    const double t1 = c1 + Zx1 * w1;
    const double t2 = c2 + Zx2 * w2;

    *mpP1_T = t1;
    *mpP1_a = a1;
    *mpP1_w = w1;
    *mpP2_T = t2;
    *mpP2_a = a2;
    *mpP2_w = w2;
}

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInertiaWithCoulombFriction, "Mechanic")

} // namespace tlmhub
