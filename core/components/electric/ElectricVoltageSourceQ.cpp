#include "core/components/electric/ElectricVoltageSourceQ.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricVoltageSourceQ::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    addInputVariable("U", "Voltage", "V", 12.0, &mpU);
}

void ElectricVoltageSourceQ::initialize()
{
    mpPel1_u = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
}

void ElectricVoltageSourceQ::simulateOneTimestep()
{
    const double U = *mpU;
    // No guard on Zc: the connected C component must supply a non-zero impedance.
    const double i = (U - *mpPel1_c) / *mpPel1_Zc;
    *mpPel1_i = i;
    *mpPel1_u = U;
}

TLMHUB_REGISTER_COMPONENT(ElectricVoltageSourceQ, "Electric")

} // namespace tlmhub
