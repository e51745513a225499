#include "core/components/mechanic/MechanicNodeSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicNodeSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Mechanic, false);
    addOutputVariable("out_f", "Force", "N", &mpOutF);
    addOutputVariable("out_v", "Velocity", "m/s", &mpOutV);
    addOutputVariable("out_x", "Position", "m", &mpOutX);
    addOutputVariable("out_c", "Wave variable", "N", &mpOutC);
    addOutputVariable("out_z", "Characteristic impedance", "N s/m", &mpOutZ);
    addOutputVariable("out_em", "Equivalent mass", "kg", &mpOutEm);
}

void MechanicNodeSensor::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_v = getSafeNodeDataPtr(mpP1, NodeMechanic::Velocity);
    mpP1_x = getSafeNodeDataPtr(mpP1, NodeMechanic::Position);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    mpP1_me = getSafeNodeDataPtr(mpP1, NodeMechanic::EquivalentMass);
    simulateOneTimestep();
}

void MechanicNodeSensor::simulateOneTimestep()
{
    *mpOutF = *mpP1_f;
    *mpOutV = *mpP1_v;
    *mpOutX = *mpP1_x;
    *mpOutC = *mpP1_c;
    *mpOutZ = *mpP1_Zc;
    *mpOutEm = *mpP1_me;
}

TLMHUB_REGISTER_COMPONENT(MechanicNodeSensor, "Mechanic")

} // namespace tlmhub
