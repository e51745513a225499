#include "core/components/electric/ElectricIsource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricIsource::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    addInputVariable("iin", "Source current", "A", 10.0, &mpIin);
}

void ElectricIsource::initialize()
{
    mpPel1_u = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
}

void ElectricIsource::simulateOneTimestep()
{
    const double c = *mpPel1_c, Zc = *mpPel1_Zc;
    const double i = *mpIin;
    const double u = c + i * Zc;
    *mpPel1_u = u;
    *mpPel1_i = i;
}

TLMHUB_REGISTER_COMPONENT(ElectricIsource, "Electric")

} // namespace tlmhub
