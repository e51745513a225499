#include "core/components/electric/ElectricUsource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricUsource::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    addInputVariable("uin", "Source voltage", "V", 12.0, &mpUin);
}

void ElectricUsource::initialize()
{
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
}

void ElectricUsource::simulateOneTimestep()
{
    *mpPel1_c = *mpUin;
    *mpPel1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(ElectricUsource, "Electric")

} // namespace tlmhub
