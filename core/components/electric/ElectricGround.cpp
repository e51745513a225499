#include "core/components/electric/ElectricGround.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricGround::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
}

void ElectricGround::initialize()
{
    // Nothing is written here: the node keeps its start values until the first step.
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
}

void ElectricGround::simulateOneTimestep()
{
    *mpPel1_c = 0.0;
    *mpPel1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(ElectricGround, "Electric")

} // namespace tlmhub
