#include "core/components/pneumatic/PneumaticPTsrc.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void PneumaticPTsrc::configure()
{
    mpPp1 = addPowerPort("Pp1", NodeType::Pneumatic);
    addInputVariable("pinput", "Pressure", "Pa", 100000.0, &mpPinput);
    addInputVariable("Tinput", "Temperature", "K", 273.0, &mpTinput);
}

void PneumaticPTsrc::initialize()
{
    mpPp1_T = getSafeNodeDataPtr(mpPp1, NodePneumatic::Temperature);
    mpPp1_c = getSafeNodeDataPtr(mpPp1, NodePneumatic::WaveVariable);
    mpPp1_Zc = getSafeNodeDataPtr(mpPp1, NodePneumatic::CharImpedance);
}

void PneumaticPTsrc::simulateOneTimestep()
{
    const double p = *mpPinput;
    const double T = *mpTinput;
    *mpPp1_T = T;
    *mpPp1_c = p;
    *mpPp1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(PneumaticPTsrc, "Pneumatic")

} // namespace tlmhub
