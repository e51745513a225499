#include "core/components/mechanic/MechanicMultiPortTranslationalMass.h"

#include "core/ComponentFactory.h"

#include <algorithm>

namespace tlmhub {

void MechanicMultiPortTranslationalMass::configure()
{
    mpP1 = addPowerMultiPort("P1", NodeType::Mechanic);
    mpP2 = addPowerMultiPort("P2", NodeType::Mechanic);
    addInputVariable("m", "Mass", "kg", 100.0, &mpM);
    addInputVariable("B", "Viscous friction coefficient", "Ns/m", 10.0, &mpB);
    addInputVariable("x_min", "Minimum position", "m", -1.0e300, &mpXMin);
    addInputVariable("x_max", "Maximum position", "m", 1.0e300, &mpXMax);
}

void MechanicMultiPortTranslationalMass::bindSide(Port* port, std::vector<SubPort>& side)
{
    const std::size_t n = getNumPorts(port);
    side.assign(n, SubPort{});
    for (std::size_t i = 0; i < n; ++i) {
        SubPort& s = side[i];
        s.f = getSafeMultiPortNodeDataPtr(port, i, NodeMechanic::Force);
        s.x = getSafeMultiPortNodeDataPtr(port, i, NodeMechanic::Position);
        s.v = getSafeMultiPortNodeDataPtr(port, i, NodeMechanic::Velocity);
        s.c = getSafeMultiPortNodeDataPtr(port, i, NodeMechanic::WaveVariable);
        s.Zc = getSafeMultiPortNodeDataPtr(port, i, NodeMechanic::CharImpedance);
        s.me = getSafeMultiPortNodeDataPtr(port, i, NodeMechanic::EquivalentMass);
        s.xStart = *s.x;
    }
}

void MechanicMultiPortTranslationalMass::initialize()
{
    bindSide(mpP1, mP1);
    bindSide(mpP2, mP2);
    if (mP1.empty() || mP2.empty()) {
        stopSimulation("Both P1 and P2 must be connected.");
        return;
    }

    // All connections of a rigid body side must start with the same velocity.
    const double v1 = *mP1[0].v;
    const double v2 = *mP2[0].v;
    for (const SubPort& s : mP1) {
        if (*s.v != v1) {
            stopSimulation("Start velocities of the P1 connections do not match.");
            return;
        }
    }
    for (const SubPort& s : mP2) {
        if (*s.v != v2) {
            stopSimulation("Start velocities of the P2 connections do not match.");
            return;
        }
    }
    if (v1 != -v2) {
        stopSimulation("Start velocities of P1 and P2 must be opposite.");
        return;
    }

    mIntegrator.initialize(mTimestep, 0.0, 0.0, mP2[0].xStart, v2);

    const double m = *mpM;
    for (SubPort& s : mP1) {
        *s.me = m;
    }
    for (SubPort& s : mP2) {
        *s.me = m;
    }
}

void MechanicMultiPortTranslationalMass::simulateOneTimestep()
{
    const double m = *mpM, B = *mpB;
    double c1 = 0.0, Zx1 = 0.0, c2 = 0.0, Zx2 = 0.0;
    for (const SubPort& s : mP1) {
        c1 += *s.c;
        Zx1 += *s.Zc;
    }
    for (const SubPort& s : mP2) {
        c2 += *s.c;
        Zx2 += *s.Zc;
    }

    mIntegrator.setDamping((B + Zx1 + Zx2) / m * mTimestep);
    mIntegrator.integrateWithUndo((c1 - c2) / m);
    double v2 = mIntegrator.valueFirst();
    double xn = mIntegrator.valueSecond();

    if (xn < *mpXMin) {
        xn = *mpXMin;
        v2 = std::max(0.0, v2);
        mIntegrator.initializeValues(0.0, xn, v2);
    }
    if (xn > *mpXMax) {
        xn = *mpXMax;
        v2 = std::min(0.0, v2);
        mIntegrator.initializeValues(0.0, xn, v2);
    }
    const double v1 = -v2;

    const double x2start0 = mP2[0].xStart;
    for (SubPort& s : mP1) {
        *s.f = *s.c + (*s.Zc) * v1;
        *s.x = s.xStart + x2start0 - xn;
        *s.v = v1;
        *s.me = m;
    }
    for (SubPort& s : mP2) {
        *s.f = *s.c + (*s.Zc) * v2;
        *s.x = s.xStart - x2start0 + xn;
        *s.v = v2;
        *s.me = m;
    }
}

TLMHUB_REGISTER_COMPONENT(MechanicMultiPortTranslationalMass, "Mechanic")

} // namespace tlmhub
