#include "core/components/hydraulic/HydraulicNodeSensor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicNodeSensor::configure()
{
    mpP1 = addReadPort("P1", NodeType::Hydraulic, false);
    addOutputVariable("p", "Pressure", "Pa", &mpOutP);
    addOutputVariable("q", "Flow", "m^3/s", &mpOutQ);
    addOutputVariable("c", "Wave variable", "", &mpOutC);
    addOutputVariable("Zc", "Characteristic impedance", "", &mpOutZc);
}

void HydraulicNodeSensor::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    simulateOneTimestep();
}

void HydraulicNodeSensor::simulateOneTimestep()
{
    *mpOutP = *mpP1_p;
    *mpOutQ = *mpP1_q;
    *mpOutC = *mpP1_c;
    *mpOutZc = *mpP1_Zc;
}

TLMHUB_REGISTER_COMPONENT(HydraulicNodeSensor, "Hydraulic")

} // namespace tlmhub
