#include "core/components/mechanic/MechanicRotationalInertiaMultiPort.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicRotationalInertiaMultiPort::configure()
{
    mpP1 = addPowerMultiPort("P1", NodeType::MechanicRotational);
    mpP2 = addPowerMultiPort("P2", NodeType::MechanicRotational);
    addInputVariable("J", "Moment of inertia", "kg m^2", 100.0, &mpJ);
    addInputVariable("B", "Viscous friction coefficient", "Nm s/rad", 10.0, &mpB);
    addInputVariable("a_min", "Minimum angle", "rad", -1.0e300, &mpAMin);
    addInputVariable("a_max", "Maximum angle", "rad", 1.0e300, &mpAMax);
}

void MechanicRotationalInertiaMultiPort::bindSide(Port* port, std::vector<SubPort>& side)
{
    const std::size_t n = getNumPorts(port);
    side.assign(n, SubPort{});
    for (std::size_t i = 0; i < n; ++i) {
        SubPort& s = side[i];
        s.f = getSafeMultiPortNodeDataPtr(port, i, NodeMechanicRotational::Torque);
        s.x = getSafeMultiPortNodeDataPtr(port, i, NodeMechanicRotational::Angle);
        s.v = getSafeMultiPortNodeDataPtr(port, i, NodeMechanicRotational::AngularVelocity);
        s.c = getSafeMultiPortNodeDataPtr(port, i, NodeMechanicRotational::WaveVariable);
        s.Zc = getSafeMultiPortNodeDataPtr(port, i, NodeMechanicRotational::CharImpedance);
        s.me = getSafeMultiPortNodeDataPtr(port, i, NodeMechanicRotational::EquivalentInertia);
        s.xStart = *s.x;
    }
}

void MechanicRotationalInertiaMultiPort::initialize()
{
    bindSide(mpP1, mP1);
    bindSide(mpP2, mP2);
    if (mP1.empty() || mP2.empty()) {
        stopSimulation("Both P1 and P2 must be connected.");
        return;
    }

    const double w1 = *mP1[0].v;
    const double w2 = *mP2[0].v;
    for (const SubPort& s : mP1) {
        if (*s.v != w1) {
            stopSimulation("Start angular velocities of the P1 connections do not match.");
            return;
        }
    }
    for (const SubPort& s : mP2) {
        if (*s.v != w2) {
            stopSimulation("Start angular velocities of the P2 connections do not match.");
            return;
        }
    }
    if (w1 != -w2) {
        stopSimulation("Start angular velocities of P1 and P2 must be opposite.");
        return;
    }

    // Starts at angle 0 and speed 0 whatever the start values (as the original).
    mIntegrator.initialize(mTimestep, 0.0, 0.0, 0.0, 0.0);

    const double J = *mpJ;
    for (SubPort& s : mP1) {
        *s.me = J;
    }
    for (SubPort& s : mP2) {
        *s.me = J;
    }
}

void MechanicRotationalInertiaMultiPort::simulateOneTimestep()
{
    const double J = *mpJ, B = *mpB;
    double c1 = 0.0, Zx1 = 0.0, c2 = 0.0, Zx2 = 0.0;
    for (const SubPort& s : mP1) {
        c1 += *s.c;
        Zx1 += *s.Zc;
    }
    for (const SubPort& s : mP2) {
        c2 += *s.c;
        Zx2 += *s.Zc;
    }

    mIntegrator.setDamping((B + Zx1 + Zx2) / J * mTimestep);
    mIntegrator.integrateWithUndo((c1 - c2) / J);
    double w2 = mIntegrator.valueFirst();
    double an = mIntegrator.valueSecond();

    if (an < *mpAMin) {
        an = *mpAMin;
        w2 = 0.0;
        mIntegrator.initializeValues(0.0, an, 0.0);
    }
    if (an > *mpAMax) {
        an = *mpAMax;
        w2 = 0.0;
        mIntegrator.initializeValues(0.0, an, 0.0);
    }
    const double w1 = -w2;

    const double a2start0 = mP2[0].xStart;
    for (SubPort& s : mP1) {
        *s.f = *s.c + (*s.Zc) * w1;
        *s.x = s.xStart + a2start0 - an;
        *s.v = w1;
        *s.me = J;
    }
    for (SubPort& s : mP2) {
        *s.f = *s.c + (*s.Zc) * w2;
        *s.x = s.xStart - a2start0 + an;
        *s.v = w2;
        *s.me = J;
    }
}

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInertiaMultiPort, "Mechanic")

} // namespace tlmhub
