#include "core/components/mechanic/MechanicBallScrew.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void MechanicBallScrew::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    mpP2 = addPowerPort("P2", NodeType::MechanicRotational);
    addInputVariable("L", "Screw lead", "m", 0.001, &mpL);
    addInputVariable("ny", "Forward efficiency", "", 0.9, &mpNy);
    addInputVariable("ny2", "Reverse efficiency", "", 0.8, &mpNy2);
    addInputVariable("J", "Moment of inertia", "kg m^2", 1.0, &mpJ);
    addInputVariable("B", "Viscous friction coefficient", "Nm s/rad", 10.0, &mpB);
    addConstant("k", "Spring coefficient", "Nm/rad", 0.0, mK);
}

void MechanicBallScrew::initialize()
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

    const double gr = (*mpL) / (2.0 * pi * (*mpNy));
    // G(s) = s/(J s^2 + B s + k); only den[1] is updated in the step.
    mDen[0] = mK;
    mDen[1] = *mpB;
    mDen[2] = *mpJ;
    mFilter.initialize(mTimestep, mNum, mDen, 0.0, 0.0);
    mIntegrator.initialize(mTimestep, 0.0, 0.0);

    *mpP1_me = (*mpJ) * gr;
}

void MechanicBallScrew::simulateOneTimestep()
{
    const double L = *mpL, ny = *mpNy, ny2 = *mpNy2, J = *mpJ, B = *mpB;
    const double v1old = *mpP1_v;
    const double w2old = *mpP2_w;

    const double g0 = L / (2.0 * pi);
    double gr = g0 / ny;
    double c1 = (*mpP1_c) * gr;
    double Zx1 = (*mpP1_Zx) * (gr * gr);
    const double c2 = *mpP2_c, Zx2 = *mpP2_Zx;

    // Power flowing backwards: use the reverse efficiency.
    if (c1 + v1old / g0 * Zx1 > c2 + w2old * Zx2) {
        gr = g0 * ny2;
        c1 = (*mpP1_c) * gr;
        Zx1 = (*mpP1_Zx) * (gr * gr);
    }

    mDen[1] = B + Zx1 + Zx2;
    mFilter.setDen(mDen);
    const double w2 = mFilter.update(c1 - c2);
    const double a2 = mIntegrator.update(w2);

    const double t2 = c2 + Zx2 * w2;
    const double v1 = -w2 * g0;
    const double x1 = -a2 * g0;
    const double f1 = (c1 + Zx1 * v1) / gr;

    *mpP1_f = f1;
    *mpP1_x = x1;
    *mpP1_v = v1;
    *mpP1_me = J * gr;
    *mpP2_T = t2;
    *mpP2_a = a2;
    *mpP2_w = w2;
}

TLMHUB_REGISTER_COMPONENT(MechanicBallScrew, "Mechanic")

} // namespace tlmhub
