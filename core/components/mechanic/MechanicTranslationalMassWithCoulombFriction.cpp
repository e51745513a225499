#include "core/components/mechanic/MechanicTranslationalMassWithCoulombFriction.h"

#include "core/ComponentFactory.h"

#include <algorithm>

namespace tlmhub {

void MechanicTranslationalMassWithCoulombFriction::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    addConstant("m", "Mass", "kg", 100.0, mMass);
    addInputVariable("b", "Viscous friction coefficient", "Ns/m", 10.0, &mpB);
    addInputVariable("f_s", "Static friction force", "N", 50.0, &mpFs);
    addInputVariable("f_k", "Kinetic friction force", "N", 45.0, &mpFk);
    addInputVariable("x_min", "Minimum position of P2", "m", -1.0e300, &mpXMin);
    addInputVariable("x_max", "Maximum position of P2", "m", 1.0e300, &mpXMax);
}

void MechanicTranslationalMassWithCoulombFriction::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zx = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP1_me = getSafeNodeDataPtr(mpP1, NodeMechanic::EquivalentMass);
    mpP2_f = getSafeNodeDataPtr(mpP2, NodeMechanic::Force);
    mpP2_x = getSafeNodeDataPtr(mpP2, NodeMechanic::Position);
    mpP2_v = getSafeNodeDataPtr(mpP2, NodeMechanic::Velocity);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeMechanic::WaveVariable);
    mpP2_Zx = getSafeNodeDataPtr(mpP2, NodeMechanic::CharImpedance);
    mpP2_me = getSafeNodeDataPtr(mpP2, NodeMechanic::EquivalentMass);

    const double f1 = *mpP1_f, f2 = *mpP2_f;
    const double x1 = *mpP1_x, x2 = *mpP2_x;
    const double v2 = *mpP2_v;

    mLength = x1 + x2;
    // u0 is the start force difference, not divided by m (as the original does).
    mIntegrator.initialize(mTimestep, 0.0, (*mpFs) / mMass, (*mpFk) / mMass, f1 - f2, x2, v2);

    *mpP1_me = mMass;
    *mpP2_me = mMass;
}

void MechanicTranslationalMassWithCoulombFriction::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zx1 = *mpP1_Zx;
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;

    mIntegrator.setFriction((*mpFs) / mMass, (*mpFk) / mMass);
    mIntegrator.setDamping(((*mpB) + Zx1 + Zx2) / mMass * mTimestep);
    mIntegrator.integrateWithUndo((c1 - c2) / mMass);
    double v2 = mIntegrator.valueFirst();
    double x2 = mIntegrator.valueSecond();

    if (x2 < *mpXMin) {
        x2 = *mpXMin;
        v2 = std::max(0.0, v2);
        mIntegrator.initializeValues(0.0, x2, v2);
    }
    if (x2 > *mpXMax) {
        x2 = *mpXMax;
        v2 = std::min(0.0, v2);
        mIntegrator.initializeValues(0.0, x2, v2);
    }

    const double v1 = -v2;
    const double x1 = -x2 + mLength;
    const double f1 = c1 + Zx1 * v1;
    const double f2 = c2 + Zx2 * v2;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP2_f = f2;
    *mpP2_x = x2;
    *mpP2_v = v2;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalMassWithCoulombFriction, "Mechanic")

} // namespace tlmhub
