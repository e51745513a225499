#include "core/components/electric/ElectricNodeSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricNodeSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Electric, false);
    addOutputVariable("u", "Voltage", "V", &mpOutU);
    addOutputVariable("i", "Current", "A", &mpOutI);
    addOutputVariable("c", "Wave variable", "V", &mpOutC);
    addOutputVariable("Zc", "Characteristic impedance", "V/A", &mpOutZc);
}

void ElectricNodeSensor::initialize()
{
    mpP1_u = getSafeNodeDataPtr(mpP1, NodeElectric::Voltage);
    mpP1_i = getSafeNodeDataPtr(mpP1, NodeElectric::Current);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeElectric::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeElectric::CharImpedance);
    simulateOneTimestep();
}

void ElectricNodeSensor::simulateOneTimestep()
{
    *mpOutU = *mpP1_u;
    *mpOutI = *mpP1_i;
    *mpOutC = *mpP1_c;
    *mpOutZc = *mpP1_Zc;
}

TLMHUB_REGISTER_COMPONENT(ElectricNodeSensor, "Electric")

} // namespace tlmhub
