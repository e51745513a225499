#include "core/components/mechanic/MechanicTranslationalCSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTranslationalCSource::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    addInputVariable("in_c", "Wave variable", "N", 0.0, &mpInC);
    addInputVariable("in_z", "Characteristic impedance", "N s/m", 0.0, &mpInZ);
}

void MechanicTranslationalCSource::initialize()
{
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanic::CharImpedance);
    simulateOneTimestep();
}

void MechanicTranslationalCSource::simulateOneTimestep()
{
    *mpP1_c = *mpInC;
    *mpP1_Zc = *mpInZ;
}

TLMHUB_REGISTER_COMPONENT(MechanicTranslationalCSource, "Mechanic")

} // namespace tlmhub
