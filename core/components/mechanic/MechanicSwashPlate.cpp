#include "core/components/mechanic/MechanicSwashPlate.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void MechanicSwashPlate::configure()
{
    addInputVariable("r", "Swivel radius", "m", 0.05, &mpR);
    addInputVariable("theta_offset", "Angle offset", "rad", 0.0, &mpOffset);
    addInputVariable("angle", "Swash plate angle", "rad", 0.0, &mpAngle);
    addInputVariable("movement", "Shaft angular velocity", "rad/s", 0.0, &mpMovement);
    addOutputVariable("torque", "Shaft torque", "Nm", &mpTorque);
    mpP1 = addPowerMultiPort("P1", NodeType::Mechanic);
}

void MechanicSwashPlate::initialize()
{
    const std::size_t n = getNumPorts(mpP1);
    mPistons.clear();
    // As in Hopsan, the piston nodes start from zero (overriding their start values),
    // so the positions oscillate around 0, and each piston's equivalent mass is 0.02 kg.
    for (std::size_t i = 0; i < n; ++i) {
        Piston p{getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::Force, 0.0),
                 getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::Position, 0.0),
                 getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::Velocity, 0.0),
                 getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::WaveVariable, 0.0),
                 getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::CharImpedance, 0.0)};
        *getSafeMultiPortNodeDataPtr(mpP1, i, NodeMechanic::EquivalentMass, 0.0) = 0.02;
        mPistons.push_back(p);
    }
    mShaftAngle.initialize(mTimestep, 0.0, 0.0);
}

void MechanicSwashPlate::simulateOneTimestep()
{
    const double angle = *mpAngle;
    const double w = *mpMovement;
    const double r = *mpR;
    const double offset = *mpOffset;
    const double stroke = r * std::tan(angle);   // half stroke of every piston
    const double spacing = 2.0 * pi / static_cast<double>(mPistons.size());
    const double shaft = mShaftAngle.update(w);

    double torque = 0.0;
    for (std::size_t i = 0; i < mPistons.size(); ++i) {
        const Piston& p = mPistons[i];
        const double phase = shaft - offset - spacing * static_cast<double>(i);
        const double v = stroke * std::cos(phase) * w;
        const double f = *p.c + *p.Zc * v;
        torque += f * stroke * std::cos(phase);
        *p.f = f;
        *p.x = stroke * std::sin(phase);
        *p.v = v;
    }
    *mpTorque = torque;
}

TLMHUB_REGISTER_COMPONENT(MechanicSwashPlate, "Mechanic")

} // namespace tlmhub
