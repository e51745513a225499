#include "core/components/mechanic/MechanicTranslationalMassWithLever.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalMassWithLever::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::Mechanic);
    addInputVariable("m", "Mass", "kg", 1.0, &mpM);
    addInputVariable("B", "Viscous friction coefficient", "Ns/m", 10.0, &mpB);
    addConstant("L_1", "Lever arm length 1", "m", 1.0, mL1);
    addConstant("L_2", "Lever arm length 2", "m", 1.0, mL2);
}

void MechanicTranslationalMassWithLever::initialize()
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
    const double x1 = *mpP1_x, v1 = *mpP1_v;
    const double m = *mpM;

    mW = (mL1 + mL2) / mL1;
    mIntegrator.initialize(mTimestep, 0.0, (f1 - f2) / m, -x1 * mW, -v1 * mW);

    *mpP2_x = -x1 * mW;
    *mpP2_v = -v1 * mW;
    *mpP1_me = m * mW;
    *mpP2_me = m;
}

void MechanicTranslationalMassWithLever::simulateOneTimestep()
{
    const double m = *mpM, B = *mpB;
    const double c1 = (*mpP1_c) / mW;
    const double Zx1 = (*mpP1_Zx) / (mW * mW);
    const double c2 = *mpP2_c;
    const double Zx2 = *mpP2_Zx;

    mIntegrator.setDamping((B + Zx1 + Zx2) / m * mTimestep);
    mIntegrator.integrateWithUndo((c1 - c2) / m);
    const double v2 = mIntegrator.valueFirst();
    const double x2 = mIntegrator.valueSecond();

    const double v1 = -v2 / mW;
    const double x1 = -x2 / mW;
    const double f1 = (c1 - Zx1 * v2) * mW;
    const double f2 = c2 + Zx2 * v2;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP1_me = m * mW;
    *mpP2_f = f2;
    *mpP2_x = x2;
    *mpP2_v = v2;
    *mpP2_me = m;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalMassWithLever, "Mechanic")

} // namespace tlmhub
