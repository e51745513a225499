#include "core/components/electric/ElectricResistor.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricResistor::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    addInputVariable("Conduct", "conductance (1/resistance)", "A/V", 0.1, &mpConduct);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Conduct"}, false);
}

void ElectricResistor::initialize()
{
    mpPel1_u = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
    mpPel2_u = getSafeNodeDataPtr(mpPel2, NodeElectric::Voltage);
    mpPel2_i = getSafeNodeDataPtr(mpPel2, NodeElectric::Current);
    mpPel2_c = getSafeNodeDataPtr(mpPel2, NodeElectric::WaveVariable);
    mpPel2_Zc = getSafeNodeDataPtr(mpPel2, NodeElectric::CharImpedance);
    // Hopsan quirk: the conductance is sampled once here and never re-read.
    mConduct = *mpConduct;
}

void ElectricResistor::simulateOneTimestep()
{
    const double c1 = *mpPel1_c, Zc1 = *mpPel1_Zc;
    const double c2 = *mpPel2_c, Zc2 = *mpPel2_Zc;
    const double Conduct = mConduct;

    const double i2 = (c1 - c2) * Conduct / (1.0 + Conduct * (Zc1 + Zc2));
    const double u1 = c1 - i2 * Zc1;
    const double u2 = c2 + i2 * Zc2;
    const double i1 = -i2;

    *mpPel1_u = u1;
    *mpPel1_i = i1;
    *mpPel2_u = u2;
    *mpPel2_i = i2;
}

TLMHUB_REGISTER_COMPONENT(ElectricResistor, "Electric")

} // namespace tlmhub
